#pragma once
// Correction: the polynomial basis H(z) that the RK correction function C(x; x - x_I) is built
// on (docs/method.md (7)-(11)). `order` is the highest degree reproduced
// exactly; `size<Dim>` the number of monomials; `evaluate` fills H and dH/dz at a scaled
// offset z = (x - x_I) / scale.

#include <Eigen/Core>
#include <concepts>
#include <string_view>

#include <rkpm/core/types.hpp>

namespace rkpm {

template <class C>
concept Correction = requires(const vec<2>& z2, const vec<1>& z1,
                              Eigen::Matrix<double, C::template size<2>, 1>& h2,
                              Eigen::Matrix<double, C::template size<2>, 2>& dh2,
                              Eigen::Matrix<double, C::template size<1>, 1>& h1,
                              Eigen::Matrix<double, C::template size<1>, 1>& dh1) {
  { C::name } -> std::convertible_to<std::string_view>;
  { C::order } -> std::convertible_to<int>;
  C::evaluate(z2, h2, dh2);
  C::evaluate(z1, h1, dh1);
};

}  // namespace rkpm
