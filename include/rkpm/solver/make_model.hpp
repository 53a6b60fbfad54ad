#pragma once
// The run-time face of the one builder (docs/method.md section 9.2): the discrete model and the
// solver of a method whose kernel, correction and quadrature rule are named at run time, by
// the policies' names in solver/policies.hpp (policies::kernels, corrections, all_quadratures).
// These three change the model's tables, not the solver's type, so a program that reads its
// method from a command line or a file compiles the time loop once per geometry, material and
// contact, and finds the model builder here:
//
//   rkpm::method_names m{"quartic", "linear", "q2+vci"};
//   auto solver = rkpm::make_solver<geometry::axisymmetric>(m, std::move(problem), options);
//
// make_model instantiates the builders of every named combination (2 x 2 x 11): a program
// should compile it once per geometry, with the models themselves (solver/model_instances.hpp:
// RKPM_INSTANTIATE_MODELS in one file per geometry, RKPM_EXTERN_MODELS in the others, which
// then see the extern declarations at the end of this header).

#include <optional>
#include <utility>

#include <boost/hana.hpp>

#include <rkpm/core/error.hpp>
#include <rkpm/solver/body_models.hpp>
#include <rkpm/solver/explicit_solver.hpp>
#include <rkpm/solver/method_names.hpp>
#include <rkpm/solver/policies.hpp>

namespace rkpm {

// The model of the method `m` in geometry G; a name that is none of the lists' is refused in
// one line that gives the choices.
template <Geometry G>
discrete_model make_model(const method_names& m, particle_set<2> particles, background_mesh mesh,
                          double max_condition, const quadrature_points* carried = nullptr) {
  namespace hana = boost::hana;
  m.check();
  std::optional<discrete_model> model;
  hana::for_each(
      hana::cartesian_product(hana::make_tuple(policies::kernels, policies::corrections, policies::all_quadratures)),
      [&](auto combo) {
        using K = typename decltype(+combo[hana::size_c<0>])::type;
        using C = typename decltype(+combo[hana::size_c<1>])::type;
        using Q = typename decltype(+combo[hana::size_c<2>])::type;
        if (!model && m.kernel == K::name && m.correction == C::name && m.quadrature == Q::name)
          model.emplace(build_model_of_bodies<K, C, Q, G>(std::move(particles), std::move(mesh), max_condition, carried));
      });
  if (!model) fail("no model for {}: not a combination of the policy lists", m.describe());
  return std::move(*model);
}

// make_model<G> of the method `m` as a solver's model_factory (explicit_solver::model_builder).
template <Geometry G>
model_factory model_factory_of(const method_names& m) {
  return [m](particle_set<2> particles, background_mesh mesh, double max_condition, const quadrature_points* carried) {
    return make_model<G>(m, std::move(particles), std::move(mesh), max_condition, carried);
  };
}

// The solver of the method `m` for problem p: make_model, then explicit_solver<G, M, Ct>.
template <Geometry G, Material M, Contact Ct>
explicit_solver<G, M, Ct> make_solver(const method_names& m, problem<M, Ct> p, const run_options& options) {
  const model_factory factory = model_factory_of<G>(m);
  discrete_model model = factory(std::move(p.particles), std::move(p.mesh), options.max_moment_condition, nullptr);
  return explicit_solver<G, M, Ct>(std::move(model), std::move(p), options, factory);
}

}  // namespace rkpm

#if defined(RKPM_EXTERN_MODELS) || defined(RKPM_INSTANTIATE_MODELS)
#include <type_traits>

#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
namespace rkpm {
// The model table's rules are exactly the shipped ones, in order; its kernels and corrections
// (four lines per rule) match the lists' lengths.
static_assert(std::is_same_v<detail::model_table_rules,
                             decltype(boost::hana::unpack(boost::hana::append(policies::all_quadratures,
                                                                              boost::hana::type_c<void>),
                                                          boost::hana::template_<detail::model_table>))::type>,
              "solver/model_instances.hpp's RKPM_MODEL_RULES must list policies::all_quadratures, in order: add the "
              "new rule there");
static_assert(decltype(boost::hana::length(policies::kernels))::value == 2 &&
                  decltype(boost::hana::length(policies::corrections))::value == 2,
              "solver/model_instances.hpp lists every shipped kernel and correction: add the new one there");
#ifdef RKPM_EXTERN_MODELS
extern template discrete_model make_model<geometry::plane_strain>(const method_names&, particle_set<2>,
                                                                  background_mesh, double, const quadrature_points*);
extern template discrete_model make_model<geometry::axisymmetric>(const method_names&, particle_set<2>,
                                                                  background_mesh, double, const quadrature_points*);
#endif
}  // namespace rkpm
#endif
