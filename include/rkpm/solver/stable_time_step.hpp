#pragma once
// Stable time step of the central-difference scheme, dt_crit = 2 / omega_max, with
// omega_max^2 the largest eigenvalue of M^-1 K (design.md section 4 "Time integration").
// K is the small-strain elastic stiffness of the discretization in its reference state,
// applied matrix-free; power iteration finds omega_max. During the run the step follows the
// current configuration: the highest frequency scales with the largest current gradient of
// the shape functions, grad_x N = F^-T grad_X N, so dt_crit(t) = dt_crit(0) * s(t) with s the
// narrowing of the supports (dynamics::support_stretch).

#include <cmath>
#include <vector>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/solver/discrete_model.hpp>

namespace rkpm {

// out = K x: internal force of the linear elastic small-strain problem for coefficients x.
template <Geometry G>
void apply_elastic_stiffness(const discrete_model& m, const material::elastic_constants& c,
                             const std::vector<vec2>& x, std::vector<vec2>& out,
                             std::vector<mat2>& stress_w, std::vector<double>& hoop_w) {
  const double lambda = c.lame_lambda(), mu = c.shear_modulus();
  const auto& t = m.at_points;
  const index_t nq = m.point_count();
#pragma omp parallel for schedule(static)
  for (index_t q = 0; q < nq; ++q) {
    mat2 H = mat2::Zero();
    vec2 u = vec2::Zero();
    for (index_t e = t.offset[q]; e < t.offset[q + 1]; ++e) {
      H += x[t.neighbor[e]] * t.grad[e].transpose();
      u += t.N[e] * x[t.neighbor[e]];
    }
    const mat2 eps = 0.5 * (H + H.transpose());
    const vec2& X = m.points.position[q];
    const double eps33 = G::out_of_plane_stretch(u, X) - 1.0;
    const double tr = eps.trace() + eps33;
    stress_w[q] = (lambda * tr * mat2::Identity() + 2.0 * mu * eps) * m.points.weight[q];
    hoop_w[q] = G::is_axisymmetric ? (lambda * tr + 2.0 * mu * eps33) * m.points.weight[q] / X[0] : 0.0;
  }
  const auto& tt = m.particles_of_points;
#pragma omp parallel for schedule(static)
  for (index_t I = 0; I < m.particle_count(); ++I) {
    vec2 f = vec2::Zero();
    for (index_t s = tt.offset[I]; s < tt.offset[I + 1]; ++s) {
      const index_t e = tt.entry[s], q = tt.point[s];
      f += stress_w[q] * t.grad[e];
      if constexpr (G::is_axisymmetric) f[0] += hoop_w[q] * t.N[e];
    }
    out[I] = f;
  }
}

// dt_crit = 2 / omega_max of the reference configuration, by power iteration on M^-1 K.
// The iteration approaches omega_max from below, so callers keep a safety fraction (< 1).
template <Geometry G>
double reference_stable_time_step(const discrete_model& m, const material::elastic_constants& c,
                                  const std::vector<double>& mass, int iterations = 100) {
  const index_t n = m.particle_count();
  std::vector<vec2> x(n), kx(n);
  std::vector<mat2> sw(m.point_count());
  std::vector<double> hw(m.point_count());
  // Deterministic start with every frequency present: a hash-like pattern per particle.
  for (index_t I = 0; I < n; ++I)
    x[I] = vec2(std::sin(12.9898 * I + 1.0), std::cos(78.233 * I + 2.0));
  double omega2 = 0.0;
  for (int it = 0; it < iterations; ++it) {
    apply_elastic_stiffness<G>(m, c, x, kx, sw, hw);
    double xkx = 0.0, xmx = 0.0;
    for (index_t I = 0; I < n; ++I) {
      xkx += x[I].dot(kx[I]);
      xmx += mass[I] * x[I].squaredNorm();
    }
    omega2 = xkx / xmx;
    double norm = 0.0;
    for (index_t I = 0; I < n; ++I) {
      x[I] = kx[I] / mass[I];
      norm = std::max(norm, x[I].cwiseAbs().maxCoeff());
    }
    if (!(norm > 0.0)) break;
    for (auto& xi : x) xi /= norm;
  }
  if (!(omega2 > 0.0) || !std::isfinite(omega2))
    fail("could not estimate the stable time step (omega^2 = {}): check the material constants "
         "and the particle masses", omega2);
  return 2.0 / std::sqrt(omega2);
}

}  // namespace rkpm
