// The runner's set-up in parts (part_setup.hpp): the refusal, and the layouts of every cell rule
// the runner offers, compiled once.

#include "part_setup.hpp"

#include <boost/hana.hpp>
#include <fmt/format.h>

#include <rkpm/solver/policies.hpp>

namespace rkpm::runner {

namespace {
namespace hana = boost::hana;

// The rules a model set up in parts can have: cell rules without corrected gradients.
constexpr auto rules_in_parts = hana::filter(policies::all_quadratures, [](auto t) {
  using Q = typename decltype(t)::type;
  return hana::bool_c<!NodalRule<Q> && !CorrectedRule<Q>>;
});

bool rule_in_parts(const std::string& name) {
  bool found = false;
  hana::for_each(rules_in_parts, [&](auto t) { found |= name == decltype(t)::type::name; });
  return found;
}
}  // namespace

std::string set_up_in_parts_refusal(const method_names& m, const background_mesh& mesh, const part_setup_request& r) {
  if (!rule_in_parts(m.quadrature))
    return fmt::format("the rule {} needs each particle's cells whole (VCI, SCNI)", m.quadrature);
  if (!mesh.cracks.empty()) return "the cells have cracks";
  if (!r.rows_reduce) return "the case's history rows do not reduce over the processes";
  if (r.rereference) return "a re-reference builds the whole model";
  if (r.cracks) return "cracks can grow: a cut builds the whole model, and rank 0 writes the snapshots whole";
  if (r.mass_scaling) return "the mass added per body is summed in particle order";
  if (r.hooks) return "a caller's hooks read the whole state";
  return {};
}

template <Geometry G>
parallel::model_layout make_layout(const method_names& m, particle_set<2> particles, background_mesh mesh,
                                   double max_condition) {
  std::optional<parallel::model_layout> layout;
  hana::for_each(hana::cartesian_product(hana::make_tuple(policies::kernels, policies::corrections, rules_in_parts)),
                 [&](auto combo) {
                   using K = typename decltype(+combo[hana::size_c<0>])::type;
                   using C = typename decltype(+combo[hana::size_c<1>])::type;
                   using Q = typename decltype(+combo[hana::size_c<2>])::type;
                   if (!layout && m.kernel == K::name && m.correction == C::name && m.quadrature == Q::name)
                     layout.emplace(parallel::make_model_layout<K, C, Q, G>(std::move(particles), std::move(mesh),
                                                                            max_condition));
                 });
  if (!layout) fail("set-up in parts of {}: not a cell rule of the policy lists", m.describe());
  return std::move(*layout);
}

template parallel::model_layout make_layout<geometry::plane_strain>(const method_names&, particle_set<2>,
                                                                    background_mesh, double);
template parallel::model_layout make_layout<geometry::axisymmetric>(const method_names&, particle_set<2>,
                                                                    background_mesh, double);

}  // namespace rkpm::runner
