#pragma once
// make_solver<Config>(problem, options): the one way to build a solver. It builds the discrete
// model with the configuration's kernel, correction and quadrature rule (one per body when the
// cells form several, solver/body_models.hpp), then the explicit solver of its geometry,
// material and contact. The solver type depends only on those three,
// so every kernel/correction/quadrature choice shares one instantiation of the time loop.
//
//   using method = rkpm::config<kernel::cubic_spline, correction::linear, quadrature::q2,
//                               geometry::axisymmetric, material::j2_plasticity<...>, ...>;
//   auto solver = rkpm::make_solver<method>(problem, options);
//   solver.run(observer, every);

#include <utility>

#include <rkpm/solver/config.hpp>
#include <rkpm/solver/body_models.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/solver/explicit_solver.hpp>

namespace rkpm {

template <class Config>
using problem_for = problem<typename Config::material_type, typename Config::contact_type>;

template <class Config>
using solver_for =
    explicit_solver<typename Config::geometry_type, typename Config::material_type, typename Config::contact_type>;

template <class Config>
solver_for<Config> make_solver(problem_for<Config> p, const run_options& options) {
  const model_factory factory = [](particle_set<2> particles, background_mesh mesh, double max_condition,
                                   const quadrature_points* carried) {
    return build_model_of_bodies<typename Config::kernel_type, typename Config::correction_type,
                                 typename Config::quadrature_type, typename Config::geometry_type>(
        std::move(particles), std::move(mesh), max_condition, carried);
  };
  discrete_model model = factory(std::move(p.particles), std::move(p.mesh), options.max_moment_condition, nullptr);
  return solver_for<Config>(std::move(model), std::move(p), options, factory);
}

}  // namespace rkpm

// The solvers a program compiled once, declared extern (solver/solver_instances.hpp).
#ifdef RKPM_EXTERN_SOLVERS
#include <rkpm/solver/solver_instances.hpp>
#endif
