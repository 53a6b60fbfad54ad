#pragma once
// Quadrature rules on the reference square [-1, 1]^2 of a background cell
// (docs/method.md section 3). Each lists (xi, eta, weight); weights sum to 4.
//   q4  2x2 Gauss, the paper's reference rule
//   q2  the paper's two-point rule, our definition: the diagonal Gauss pair
//       (-1/sqrt3, -1/sqrt3), (+1/sqrt3, +1/sqrt3), weight 2 each. Exact for 1, xi, eta,
//       xi^2, eta^2 and every cubic; misses only xi*eta
//   q9  3x3 Gauss, a reference for tests
//   q1  one centre point: under-integrates and has spurious zero-energy modes; shipped
//       only so that tests can show the failure the other rules avoid

#include <array>
#include <string_view>

namespace rkpm::quadrature {

namespace detail {
inline constexpr double g2 = 0.57735026918962576451;  // 1/sqrt(3)
inline constexpr double g3 = 0.77459666924148337704;  // sqrt(3/5)
inline constexpr double w3a = 5.0 / 9.0, w3b = 8.0 / 9.0;
}  // namespace detail

struct q1 {
  static constexpr std::string_view name = "q1";
  static constexpr int points_per_cell = 1;
  static constexpr std::array<std::array<double, 3>, 1> rule{{{0.0, 0.0, 4.0}}};
};

struct q2 {
  static constexpr std::string_view name = "q2";
  static constexpr int points_per_cell = 2;
  static constexpr std::array<std::array<double, 3>, 2> rule{
      {{-detail::g2, -detail::g2, 2.0}, {detail::g2, detail::g2, 2.0}}};
};

struct q4 {
  static constexpr std::string_view name = "q4";
  static constexpr int points_per_cell = 4;
  static constexpr std::array<std::array<double, 3>, 4> rule{{{-detail::g2, -detail::g2, 1.0},
                                                              {detail::g2, -detail::g2, 1.0},
                                                              {detail::g2, detail::g2, 1.0},
                                                              {-detail::g2, detail::g2, 1.0}}};
};

struct q9 {
  static constexpr std::string_view name = "q9";
  static constexpr int points_per_cell = 9;
  static constexpr std::array<std::array<double, 3>, 9> rule = [] {
    constexpr double x[3] = {-detail::g3, 0.0, detail::g3};
    constexpr double w[3] = {detail::w3a, detail::w3b, detail::w3a};
    std::array<std::array<double, 3>, 9> r{};
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) r[3 * j + i] = {x[i], x[j], w[i] * w[j]};
    return r;
  }();
};

}  // namespace rkpm::quadrature
