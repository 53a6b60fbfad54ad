#pragma once
// Kernel: a 1D window profile phi(z) with support |z| <= 1, even, normalised to unit
// integral, with first and second derivatives. The 2D window is the tensor product
// Phi_a(x) = prod_k phi(x_k / a_k) / a_k  (docs/method.md (4)-(6)).

#include <concepts>
#include <string_view>

namespace rkpm {

template <class K>
concept Kernel = requires(double z) {
  { K::name } -> std::convertible_to<std::string_view>;
  { K::value(z) } -> std::same_as<double>;
  { K::derivative(z) } -> std::same_as<double>;
  { K::second_derivative(z) } -> std::same_as<double>;
};

}  // namespace rkpm
