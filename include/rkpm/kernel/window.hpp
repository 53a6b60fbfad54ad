#pragma once
// Tensor-product window Phi_a(x) = prod_k phi(x_k / a_k) / a_k with a separate support a_k per
// direction (docs/method.md (6), section 2.3: the Taylor bar's 0.16 mm x 0.648 mm spacing needs it), and
// its gradient with respect to x.

#include <rkpm/concepts/kernel.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm::kernel {

template <Kernel K, int Dim>
struct window_value {
  double value = 0.0;
  vec<Dim> gradient = vec<Dim>::Zero();
};

// Window value and gradient at offset dx = x - x_I for supports a (all a_k > 0).
template <Kernel K, int Dim>
window_value<K, Dim> window(const vec<Dim>& dx, const vec<Dim>& a) {
  double phi[Dim];
  double dphi[Dim];
  for (int k = 0; k < Dim; ++k) {
    const double z = dx[k] / a[k];
    phi[k] = K::value(z) / a[k];
    dphi[k] = K::derivative(z) / (a[k] * a[k]);
  }
  window_value<K, Dim> w;
  w.value = 1.0;
  for (int k = 0; k < Dim; ++k) w.value *= phi[k];
  for (int k = 0; k < Dim; ++k) {
    double g = dphi[k];
    for (int j = 0; j < Dim; ++j)
      if (j != k) g *= phi[j];
    w.gradient[k] = g;
  }
  return w;
}

// True when x lies strictly inside the rectangular support of a particle at offset dx.
template <int Dim>
bool in_support(const vec<Dim>& dx, const vec<Dim>& a) {
  for (int k = 0; k < Dim; ++k)
    if (!(std::abs(dx[k]) < a[k])) return false;
  return true;
}

}  // namespace rkpm::kernel
