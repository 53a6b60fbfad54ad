#pragma once
// explicit_solver<Config>: the solver type of one configuration. It builds the discrete model
// with the configuration's kernel, correction and quadrature, then integrates with the
// dynamics of its geometry, material and contact (solver/dynamics.hpp).
//
//   using method = rkpm::config<kernel::cubic_spline, correction::linear, quadrature::q2,
//                               geometry::axisymmetric, material::j2_plasticity<...>, ...>;
//   rkpm::explicit_solver<method> solver(problem, options);
//   solver.run(observer, every);

#include <rkpm/solver/config.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/dynamics.hpp>

namespace rkpm {

template <class Config>
using problem_for = problem<typename Config::material_type, typename Config::contact_type>;

template <class Config>
class explicit_solver
    : public dynamics<typename Config::geometry_type, typename Config::material_type, typename Config::contact_type> {
  using base = dynamics<typename Config::geometry_type, typename Config::material_type, typename Config::contact_type>;

 public:
  using config_type = Config;

  explicit_solver(problem_for<Config> p, run_options options)
      : explicit_solver(build_model(p, options), std::move(p), options) {}

 private:
  // Delegation keeps the order explicit: the model is built from the problem before the
  // problem is moved into the dynamics.
  explicit_solver(discrete_model model, problem_for<Config>&& p, run_options options)
      : base(std::move(model), std::move(p), options) {}

  static discrete_model build_model(const problem_for<Config>& p, const run_options& options) {
    return build_discrete_model<typename Config::kernel_type, typename Config::correction_type,
                                typename Config::quadrature_type, typename Config::geometry_type>(
        p.particles, p.mesh, options.max_moment_condition);
  }
};

}  // namespace rkpm
