#pragma once
// The definition of build_model (model_builder.hpp): a run-time search of the Hana product of
// methods.hpp's kernels, corrections and quadrature rules for the names asked for; one model per
// body when the cells form several (solver/body_models.hpp).

#include <optional>
#include <string_view>
#include <utility>

#include <boost/hana.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <rkpm/core/error.hpp>
#include <rkpm/solver/body_models.hpp>

#include "methods.hpp"
#include "model_builder.hpp"

namespace rkpm::runner {

template <class Geometry>
discrete_model build_model(std::string_view kernel, std::string_view correction, std::string_view rule,
                           particle_set<2> particles, background_mesh mesh, double max_condition) {
  std::optional<discrete_model> model;
  hana::for_each(hana::cartesian_product(hana::make_tuple(kernels, corrections, quadratures)), [&](auto combo) {
    using K = typename decltype(+combo[hana::size_c<0>])::type;
    using C = typename decltype(+combo[hana::size_c<1>])::type;
    using Q = typename decltype(+combo[hana::size_c<2>])::type;
    if (!model && kernel == K::name && correction == C::name && rule == Q::name)
      model.emplace(build_model_of_bodies<K, C, Q, Geometry>(std::move(particles), std::move(mesh), max_condition));
  });
  if (!model)
    fail("no compiled model for kernel '{}', correction '{}', quadrature '{}'; the choices are {}; {}; {}", kernel,
         correction, rule, fmt::join(policy_names(kernels), ", "), fmt::join(policy_names(corrections), ", "),
         fmt::join(policy_names(quadratures), ", "));
  return std::move(*model);
}

}  // namespace rkpm::runner
