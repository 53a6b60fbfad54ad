// Self-contact and contact between any pieces (contact/body_contact.hpp, body_pair_surfaces.hpp;
// docs/method.md section 6.11):
//   - a thin elastic ring squashed between two rigid plates until its inner surfaces meet: with
//     the self pair (0, 0) no inner-surface particle goes through the opposite inner surface
//     (measured from the particles' positions, not from the contact's report) and the plates'
//     force rises once the inner surfaces touch; without it they pass through each other;
//     all_body_pairs on one body gives the self pair's result bit for bit;
//   - two equal bars thrown at each other in all-pairs mode, no pair declared: they part after
//     2 L / c with their velocities reversed (1D wave theory), momentum is kept to round-off, the
//     energy balance closes with the contact work, and the run is that of the declared pairs
//     (1, 0) and (0, 1), bit for bit;
//   - a soft bar cut clean through before the run (cut_cells), its two pieces thrown at each other:
//     in all-pairs mode the crack faces (docs/method.md (114)) are masters and slaves, and the
//     pieces rebound with no face point behind the other piece's face by more than 2% of h
//     (measured from the positions), momentum kept to round-off and the energy balance closed with
//     the contact work; without contact the faces pass through each other by more than h;
//   - nothing touching (a block dropped on a floor): a self pair or all pairs change no bit;
//   - bad input: one line each.
// Only solvers of include/rkpm/solver/solver_instances.hpp (plane strain, elastic, effective-mass
// contact), so the file instantiates no solver of its own.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/discretization/mesh_particles.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "support/body_momentum.hpp"
#include "support/error_message.hpp"

namespace test_numeric_self_contact {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

template <class Ct>
using plane_elastic = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                             material::elastic, Ct>;
using coulomb_t = contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::coulomb>;
using frictionless_t =
    contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::frictionless>;

bool same_bits(const std::vector<vec2>& a, const std::vector<vec2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i][0] != b[i][0] || a[i][1] != b[i][1]) return false;
  return true;
}

// ---- The ring: radii 8 and 10 mm, 3 particles across and 48 around (node j * 3 + i at radius
// index i and angle 2 pi j / 48; its nodes are its particles), squashed by plates moving at V
// from y = +-10 mm to a gap of 3.6 mm: the walls fall inward, so the inner surfaces meet at a
// gap of about 4.9 mm, and the two walls of 2 mm end squeezed by 10%.
constexpr double r_in = 8e-3, r_out = 10e-3, V = 5.0, final_gap = 3.6e-3;
constexpr int across = 3, around = 48;
constexpr double h_radial = (r_out - r_in) / (across - 1);

background_mesh ring_mesh() {
  background_mesh m;
  for (int j = 0; j < around; ++j)
    for (int i = 0; i < across; ++i) {
      const double r = r_in + h_radial * i, theta = 2.0 * std::numbers::pi * j / around;
      m.node.push_back(vec2(r * std::cos(theta), r * std::sin(theta)));
    }
  for (int j = 0; j < around; ++j)
    for (int i = 0; i + 1 < across; ++i) {
      const int k = (j + 1) % around;  // closes the ring: no seam
      m.cell.push_back({j * across + i, j * across + i + 1, k * across + i + 1, k * across + i});
    }
  return m;
}

struct squash {
  double deepest = 0.0;        // deepest inner particle through the opposite inner surface, / h_radial
  double first_touch = -1.0;   // time of the first self-contact
  std::vector<double> time, impulse;  // the top plate's impulse (N s per m) after each step
  std::vector<vec2> d, v;      // coefficients at the end
  double mean_force(double t1, double t2) const {  // the top plate's mean force over [t1, t2]
    auto at = [&](double t) {
      const auto k = std::lower_bound(time.begin(), time.end(), t) - time.begin();
      return impulse[std::min<std::size_t>(k, time.size() - 1)];
    };
    return (at(t2) - at(t1)) / (t2 - t1);
  }
};

// How far inner-surface particle P has gone through the opposite inner surface: the chain of
// inner particles at angles j0..j1 (x increasing along it), its height at P's x interpolated,
// positive when P is beyond it (below it for `from_above`).
double through(const std::vector<vec2>& x, const vec2& P, int j0, int j1, int dj, bool from_above) {
  for (int j = j0; j != j1; j += dj) {
    const vec2& a = x[j * across];
    const vec2& b = x[(j + dj) * across];
    if (P[0] < a[0] || P[0] > b[0]) continue;
    const double y = a[1] + (b[1] - a[1]) * (P[0] - a[0]) / (b[0] - a[0]);
    return from_above ? y - P[1] : P[1] - y;
  }
  return 0.0;
}

squash squash_ring(coulomb_t contact) {
  const background_mesh mesh = ring_mesh();
  problem_for<plane_elastic<coulomb_t>> p{.particles = particles_from_mesh(mesh, 2.0),
                                          .mesh = mesh,
                                          .material = material::elastic({1e7, 0.3, 1000.0}),
                                          .contact = std::move(contact)};
  run_options o;
  o.end_time = (2.0 * r_out - final_gap) / (2.0 * V);
  auto s = make_solver<plane_elastic<coulomb_t>>(std::move(p), o);
  squash r;
  while (s.time() < o.end_time * (1.0 - 1e-12)) {
    s.step();
    r.time.push_back(s.time());
    r.impulse.push_back(s.tool_impulses()[0][1]);
    if (r.first_touch < 0.0 && !s.contact().bodies().active_pairs().empty()) r.first_touch = s.time();
    // The upper inner surface (angles 30 to 150 degrees, j = 4..20) against the lower (j = 28..44),
    // and the other way round, where both are about flat.
    const auto x = s.particle_positions();
    for (int j = 4; j <= 20; ++j) {
      r.deepest = std::max(r.deepest, through(x, x[j * across], 28, 44, 1, true) / h_radial);
      r.deepest = std::max(r.deepest, through(x, x[(j + 24) * across], 20, 4, -1, false) / h_radial);
    }
  }
  r.d = s.coefficients();
  r.v = s.coefficient_velocities();
  return r;
}

std::vector<contact::rigid_tool> plates() {
  using contact::rigid_tool;
  return {rigid_tool("top", {vec2(30e-3, r_out), vec2(-30e-3, r_out)}, contact::side::left,
                     contact::tool_motion::constant_velocity(vec2(0.0, -V)), 2e-3),
          rigid_tool("bottom", {vec2(-30e-3, -r_out), vec2(30e-3, -r_out)}, contact::side::left,
                     contact::tool_motion::constant_velocity(vec2(0.0, V)), 2e-3)};
}

}  // namespace

TEST_CASE("self-contact: a ring squashed flat keeps its inner surfaces apart, and the plates feel it") {
  const contact::friction::coulomb mu{0.1};
  const squash on = squash_ring(coulomb_t(plates(), {contact::body_pair{0, 0}}, mu));
  const squash off = squash_ring(coulomb_t(plates(), mu));
  const squash all = squash_ring(coulomb_t(plates(), contact::all_body_pairs, mu));
  const double T = on.time.back(), window = 0.05 * T;
  REQUIRE(on.first_touch > 0.0);
  const double before = on.mean_force(on.first_touch - window, on.first_touch);
  const double end_on = on.mean_force(T - window, T), end_off = off.mean_force(T - window, T);
  MESSAGE("first self-contact at " << on.first_touch * 1e3 << " ms of " << T * 1e3 << " ms (plate gap "
                                   << (2.0 * r_out - 2.0 * V * on.first_touch) * 1e3 << " mm); deepest inner particle "
                                   << "through the other inner surface: " << on.deepest << " h with self-contact, "
                                   << off.deepest << " h without; plate force before the touch " << before
                                   << " N/m, at the end " << end_on << " N/m (" << end_off << " N/m without)");
  CHECK(on.deepest < 0.02);
  CHECK(off.deepest > 0.2);  // the test can fail: without the self pair the surfaces cross
  CHECK(end_on > 2.0 * before);
  CHECK(end_on > 1.5 * end_off);
  CHECK(same_bits(all.d, on.d));  // one body: all pairs is the self pair
  CHECK(same_bits(all.v, on.v));
}

namespace {

// ---- Two equal steel bars (plane strain, Poisson ratio 0: 1D bars with c = sqrt(E / rho)), of
// 40 spacings, at +-1 m/s, as in bodies_in_contact.cpp.
constexpr double E = 200e9, rho = 7800.0, L = 10e-3, H = 1.5e-3, h = 0.25e-3, gap0 = 0.01 * h, W = 1.0;
const double c = std::sqrt(E / rho);

void add_bar(const vec2& lo, const vec2& hi, particle_set<2>& p, background_mesh& m) {
  const Eigen::Vector2i n(static_cast<int>(std::lround((hi - lo)[0] / h)) + 1,
                          static_cast<int>(std::lround((hi - lo)[1] / h)) + 1);
  append_body(p, m, make_grid_particles<2>(lo, hi, n, 2.0), make_grid_mesh(lo, hi, n));
}

struct impact {
  double contact_start = -1.0, contact_end = -1.0, v0 = 0.0, v1 = 0.0;
  double momentum_error = 0.0, worst_inside = 0.0, balance = 0.0, contact_work = 0.0, K0 = 0.0;
  std::vector<vec2> d, v;
};

impact collide(frictionless_t contact) {
  using Cfg = plane_elastic<frictionless_t>;
  particle_set<2> particles;
  background_mesh mesh;
  add_bar(vec2(-L, 0.0), vec2(0.0, H), particles, mesh);
  add_bar(vec2(gap0, 0.0), vec2(gap0 + L, H), particles, mesh);
  problem_for<Cfg> p{.particles = std::move(particles),
                     .mesh = std::move(mesh),
                     .material = material::elastic({E, 0.0, rho}),
                     .contact = std::move(contact),
                     .initial_velocity = [](const vec2& X) { return vec2(X[0] < 0.5 * gap0 ? W : -W, 0.0); }};
  run_options o;
  o.end_time = gap0 / (2.0 * W) + 1.6 * 2.0 * L / c;
  auto s = make_solver<Cfg>(std::move(p), o);
  const auto n = s.model().particle_count();
  auto momentum = [&](int body) { return test::body_momentum_x(s, body); };  // body -1: both
  const double P0 = momentum(-1).first, m0 = momentum(0).second;
  impact r;
  r.K0 = s.kinetic_energy();
  while (s.time() < o.end_time * (1.0 - 1e-12)) {
    s.step();
    r.momentum_error = std::max(r.momentum_error, std::abs(momentum(-1).first - P0) / (m0 * W));
    if (s.last_contact().active > 0) {
      if (r.contact_start < 0.0) r.contact_start = s.time();
      r.contact_end = s.time();
    }
    const auto x = s.particle_positions();
    double face0 = -1e300, face1 = 1e300;
    for (index_t I = 0; I < n; ++I)
      if (s.body_of_particle(I) == 0) face0 = std::max(face0, x[I][0]);
      else face1 = std::min(face1, x[I][0]);
    r.worst_inside = std::max(r.worst_inside, (face0 - face1) / h);
  }
  r.v0 = momentum(0).first / m0;
  r.v1 = momentum(1).first / momentum(1).second;
  r.balance = std::abs(s.energy().imbalance()) / r.K0;
  r.contact_work = s.energy().contact / r.K0;
  r.d = s.coefficients();
  r.v = s.coefficient_velocities();
  return r;
}

}  // namespace

TEST_CASE("self-contact leaves out the segments within a slave's kernel reach, and only those") {
  // The ring's particles placed by hand (coefficients d solving sum_K N_K(X_I) d_K = u_I), with
  // the self pair called directly: (a) inner particle 36 (angle 90 degrees) folded 0.2 h behind
  // the segment of its neighbours 39 and 42 (97.5 and 105 degrees), both in its row: a fold the
  // segment catches, and the self pair leaves it alone; (b) inner particle 30 (75 degrees)
  // carried across the hole, 0.2 h behind the segment of 105 and 108 (262.5 and 270 degrees),
  // far from its kernel: caught. (The mutation that excludes only a and b themselves fails (a).)
  const background_mesh mesh = ring_mesh();
  problem_for<plane_elastic<coulomb_t>> p{.particles = particles_from_mesh(mesh, 2.0),
                                          .mesh = mesh,
                                          .material = material::elastic({1e7, 0.3, 1000.0}),
                                          .contact = coulomb_t(plates(), {contact::body_pair{0, 0}})};
  run_options o;
  o.end_time = 1e-6;
  const auto s = make_solver<plane_elastic<coulomb_t>>(std::move(p), o);
  const auto& rows = s.model().at_particles;
  const auto& X = s.model().particles.position;
  const auto n = s.model().particle_count();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (index_t I = 0; I < n; ++I)
    for (index_t e = rows.offset[I]; e < rows.offset[I + 1]; ++e) A(I, rows.neighbor[e]) = rows.N[e];
  const auto lu = A.partialPivLu();
  // Particle J at the middle of segment a-b, `depth` behind it (away from the hole's centre).
  auto placed = [&](index_t J, index_t a, index_t b, double depth) {
    const vec2 mid = 0.5 * (X[a] + X[b]);
    const vec2 P = mid + depth * mid.normalized();
    Eigen::VectorXd ux = Eigen::VectorXd::Zero(n), uy = Eigen::VectorXd::Zero(n);
    ux[J] = P[0] - X[J][0];
    uy[J] = P[1] - X[J][1];
    const Eigen::VectorXd dx = lu.solve(ux), dy = lu.solve(uy);
    std::vector<vec2> d(n);
    for (index_t I = 0; I < n; ++I) d[I] = vec2(dx[I], dy[I]);
    contact::body_contact self({contact::body_pair{0, 0}});
    self.setup(s.body(), s.slave_particles());
    std::vector<vec2> v(n, vec2::Zero());
    contact_result r;
    self.enforce(s.body(), 1e-6, contact::enforcement::effective_mass{}, contact::friction::frictionless{}, d, v, r);
    // The geometry alone: J behind segment a-b, at its physical position.
    std::vector<vec2> x(n);
    for (index_t I = 0; I < n; ++I) x[I] = X[I] + vec2(ux[I], uy[I]);
    const std::array<std::array<index_t, 2>, 2> both_ways{{{a, b}, {b, a}}};
    const auto hit = contact::penetrated_segment(std::span<const std::array<index_t, 2>>(both_ways),
                                                 std::array<index_t, 2>{0, 1}, x, x[J], 0.5 * h_radial);
    return std::tuple{std::vector<contact::body_contact_pair>(self.active_pairs().begin(), self.active_pairs().end()),
                      hit.segment >= 0, contact::within_kernel_reach(rows, J, a, b)};
  };
  const auto [fold, fold_caught, fold_near] = placed(36, 39, 42, 0.2 * h_radial);
  const auto [far, far_caught, far_near] = placed(30, 105, 108, 0.2 * h_radial);
  MESSAGE("fold: " << fold.size() << " self-contacts (the segment catches it: " << fold_caught
                   << "); across the hole: " << far.size() << " self-contacts");
  CHECK(fold_caught);
  CHECK(fold_near);
  CHECK(fold.empty());
  CHECK(far_caught);
  CHECK(!far_near);
  // Particle 30's own segments now cross the hole too, and may catch a particle there: only its
  // contact is asked for.
  const auto q = std::find_if(far.begin(), far.end(), [](const auto& c) { return c.slave == 30; });
  REQUIRE(q != far.end());
  CHECK(std::min(q->a, q->b) == 105);
  CHECK(std::max(q->a, q->b) == 108);
  CHECK(std::abs(q->gap - 0.2 * h_radial) < 0.05 * h_radial);
}

TEST_CASE("all pairs: two bars thrown at each other rebound after 2L/c, as the declared pairs (1, 0) and (0, 1)") {
  const impact all = collide(frictionless_t({}, contact::all_body_pairs));
  const impact declared = collide(frictionless_t({}, {contact::body_pair{1, 0}, contact::body_pair{0, 1}}));
  const double duration = all.contact_end - all.contact_start;
  MESSAGE("contact " << duration * 1e6 << " us against 2L/c = " << 2.0 * L / c * 1e6 << " us; velocities after "
                     << all.v0 << ", " << all.v1 << " m/s; momentum error " << all.momentum_error
                     << "; deepest face overlap " << all.worst_inside << " h; energy imbalance " << all.balance
                     << " of K0 with contact work " << all.contact_work << " K0");
  CHECK(std::abs(duration - 2.0 * L / c) < 0.05 * 2.0 * L / c);
  CHECK(std::abs(all.v0 + W) < 0.05 * W);
  CHECK(std::abs(all.v1 - W) < 0.05 * W);
  CHECK(all.momentum_error < 1e-12);
  CHECK(all.worst_inside < 0.02);
  CHECK(all.balance < 0.01);
  CHECK(all.contact_work < 0.0);  // the contact takes the energy the discrete impact leaves as vibration
  CHECK(same_bits(all.d, declared.d));
  CHECK(same_bits(all.v, declared.v));
}

namespace {

// ---- A soft bar (Poisson ratio 0: c = 100 m/s) of 81 x 6 cells of h, its middle column of cells
// (the 41st) cut across before the run as a crack cuts them: two pieces of 40.5 h, no row joining
// them, thrown at each other at +-V_cut. Without contact they pass through each other freely, by
// 2 V_cut t, 2.6 h by the end.
constexpr double E_soft = 1e7, rho_soft = 1000.0, V_cut = 1.0;
constexpr int cells_along = 81, cut_column = 40;
constexpr double cut_at = (cut_column + 0.5) * h;  // the crack's x, and each piece's length

struct cut_impact {
  index_t pieces = 0;
  index_t face_contacts = 0;  // contacts of a face point or on a face, summed over the steps
  double deepest = 0.0;       // deepest face point behind the other piece's face over the run, / h
  double worst_row_error = 0.0;  // of the faces' rows: |sum N - 1| + |sum N X - P| / h
  bool rows_one_sided = true;    // every face row of one piece
  double momentum_error = 0.0, v_left = 0.0, v_right = 0.0, balance = 0.0, contact_work = 0.0;
};

// How far the face points of one piece are behind the faces of the other, at coefficients d:
// -(x_p - x_a) . n for each face point p and each face a-b of the other piece that p projects
// onto (lambda in [0, 1]), n the face's outward normal; the largest.
double deepest_behind_faces(const crack_face_rows& f, const std::vector<vec2>& d, const std::vector<char>& left) {
  std::vector<vec2> x(f.points());
  for (index_t p = 0; p < f.points(); ++p) x[p] = f.position[p] + f.rows.interpolate(p, d);
  const auto piece = [&](index_t face) { return left[f.rows.neighbor[f.rows.offset[f.segment[face][0]]]]; };
  double deepest = 0.0;
  for (index_t g = 0; g < f.faces(); ++g)
    for (index_t k = 0; k < f.faces(); ++k) {
      if (piece(g) == piece(k)) continue;
      const auto [a, b] = f.segment[k];
      const vec2 t = x[b] - x[a];
      const vec2 n = vec2(t[1], -t[0]) / t.norm();
      for (const index_t p : f.segment[g]) {
        const double lambda = (x[p] - x[a]).dot(t) / t.squaredNorm();
        if (lambda >= 0.0 && lambda <= 1.0) deepest = std::max(deepest, -(x[p] - x[a]).dot(n));
      }
    }
  return deepest;
}

cut_impact collide_cut_bar(frictionless_t contact) {
  using Cfg = plane_elastic<frictionless_t>;
  const vec2 lo(0.0, 0.0), hi(cells_along * h, H);
  const Eigen::Vector2i n(cells_along + 1, static_cast<int>(std::lround(H / h)) + 1);
  problem_for<Cfg> p{.particles = make_grid_particles<2>(lo, hi, n, 2.0),
                     .mesh = make_grid_mesh(lo, hi, n),
                     .material = material::elastic({E_soft, 0.0, rho_soft}),
                     .contact = std::move(contact),
                     .initial_velocity = [](const vec2& X) { return vec2(X[0] < cut_at ? V_cut : -V_cut, 0.0); }};
  run_options o;
  o.end_time = 1.6 * 2.0 * cut_at / std::sqrt(E_soft / rho_soft);
  auto s = make_solver<Cfg>(std::move(p), o);
  std::vector<std::pair<index_t, vec2>> column;
  for (index_t row = 0; row + 1 < n[1]; ++row) column.emplace_back(row * cells_along + cut_column, vec2(1.0, 0.0));
  s.cut_cells(column);

  const discrete_model& m = s.model();
  const index_t np = m.particle_count();
  std::vector<char> left(np);
  double M = 0.0, M_left = 0.0;
  for (index_t I = 0; I < np; ++I) {
    left[I] = s.initial_positions()[I][0] < cut_at;
    M += s.mass()[I];
    M_left += left[I] ? s.mass()[I] : 0.0;
  }
  cut_impact r;
  r.pieces = s.fragments().pieces;
  const crack_face_rows& f = m.crack_faces;
  for (index_t q = 0; q < f.points(); ++q) {
    double sum = 0.0;
    vec2 X = vec2::Zero();
    for (index_t e = f.rows.offset[q]; e < f.rows.offset[q + 1]; ++e) {
      sum += f.rows.N[e];
      X += f.rows.N[e] * m.particles.position[f.rows.neighbor[e]];
      r.rows_one_sided &= left[f.rows.neighbor[e]] == left[f.rows.neighbor[f.rows.offset[q]]];
    }
    r.worst_row_error = std::max(r.worst_row_error, std::abs(sum - 1.0) + (X - f.position[q]).norm() / h);
  }
  const auto momentum = [&](int piece) {  // -1: both
    double P = 0.0;
    for (index_t I = 0; I < np; ++I)
      if (piece < 0 || left[I] == piece) P += s.mass()[I] * s.coefficient_velocities()[I][0];
    return P;
  };
  const double P0 = momentum(-1), K0 = s.kinetic_energy();
  while (s.before_end()) {
    s.step_to_end();
    r.momentum_error = std::max(r.momentum_error, std::abs(momentum(-1) - P0) / (M * V_cut));
    r.deepest = std::max(r.deepest, deepest_behind_faces(s.model().crack_faces, s.coefficients(), left) / h);
    if constexpr (requires { s.contact().bodies(); })
      for (const auto& c : s.contact().bodies().active_pairs()) r.face_contacts += c.slave >= np || c.a >= np;
  }
  r.v_left = momentum(1) / M_left;
  r.v_right = momentum(0) / (M - M_left);
  r.balance = std::abs(s.energy().imbalance()) / K0;
  r.contact_work = s.energy().contact / K0;
  return r;
}

}  // namespace

TEST_CASE("crack faces: the two pieces of a bar cut through rebound at the cut instead of passing through") {
  const cut_impact on = collide_cut_bar(frictionless_t({}, contact::all_body_pairs));
  const cut_impact off = collide_cut_bar(frictionless_t({}));
  MESSAGE("faces' rows: reproducing to " << on.worst_row_error << ", one-sided " << on.rows_one_sided
                                         << "; deepest face point behind the other face " << on.deepest
                                         << " h with all pairs (" << on.face_contacts << " face contacts), " << off.deepest
                                         << " h without contact; velocities after " << on.v_left << ", " << on.v_right
                                         << " m/s; momentum error " << on.momentum_error << "; energy imbalance "
                                         << on.balance << " of K0 with contact work " << on.contact_work << " K0");
  CHECK(on.pieces == 2);
  CHECK(on.worst_row_error < 1e-12);
  CHECK(on.rows_one_sided);
  CHECK(off.deepest > 1.0);  // the test can fail: without contact the pieces pass through each other
  CHECK(on.face_contacts > 0);
  CHECK(on.deepest < 0.02);
  CHECK(on.deepest < 0.005);  // 0.018 h when a face catches nothing past its ends: joints slip through
  CHECK(on.v_left < -0.9 * V_cut);  // rebound: 1D wave theory gives the velocities reversed after 2 L / c
  CHECK(on.v_right > 0.9 * V_cut);
  CHECK(on.momentum_error < 1e-13);
  CHECK(on.balance < 0.01);
  CHECK(on.contact_work < 0.0);
  CHECK(-on.contact_work > 2.0 * on.balance);  // the balance closes because the contact work is booked
}

TEST_CASE("nothing touching: a self pair and all pairs change no bit of a block dropped on a floor") {
  // A block dropped on a rigid floor under gravity bulges at its foot; no part of its surface
  // comes near another, so the self pair finds nothing and the run is the tools' alone.
  constexpr double s = 1e-3;
  auto drop = [&](coulomb_t contact) {
    const vec2 lo(0.0, 0.1 * s), hi(10.0 * s, 6.1 * s);
    const Eigen::Vector2i n(11, 7);
    problem_for<plane_elastic<coulomb_t>> p{.particles = make_grid_particles<2>(lo, hi, n, 2.0),
                                            .mesh = make_grid_mesh(lo, hi, n),
                                            .material = material::elastic({1e7, 0.3, 1000.0}),
                                            .contact = std::move(contact),
                                            .initial_velocity = [](const vec2&) { return vec2(0.0, -2.0); },
                                            .body_force = vec2(0.0, -1000.0)};
    run_options o;
    o.end_time = 2e-3;
    auto solver = make_solver<plane_elastic<coulomb_t>>(std::move(p), o);
    std::size_t body_contacts = 0, tool_contacts = 0;
    while (solver.time() < o.end_time * (1.0 - 1e-12)) {
      solver.step();
      body_contacts += solver.contact().bodies().active_pairs().size();
      tool_contacts += solver.contact().active_pairs().size();
    }
    return std::tuple{solver.coefficients(), solver.coefficient_velocities(), body_contacts, tool_contacts};
  };
  auto floor = [] {
    return std::vector<contact::rigid_tool>{
        contact::rigid_tool("floor", {vec2(-0.1, 0.0), vec2(0.1, 0.0)}, contact::side::left, {}, 1e-3)};
  };
  const contact::friction::coulomb mu{0.2};
  const auto [d_off, v_off, body_off, tool_off] = drop(coulomb_t(floor(), mu));
  const auto [d_self, v_self, body_self, tool_self] = drop(coulomb_t(floor(), {contact::body_pair{0, 0}}, mu));
  const auto [d_all, v_all, body_all, tool_all] = drop(coulomb_t(floor(), contact::all_body_pairs, mu));
  MESSAGE(tool_off << " slave-steps on the floor; self contacts " << body_self << " (self pair), " << body_all
                   << " (all pairs)");
  CHECK(tool_off > 100);  // the block lands and bulges
  CHECK(body_self == 0);
  CHECK(body_all == 0);
  CHECK(same_bits(d_self, d_off));
  CHECK(same_bits(v_self, v_off));
  CHECK(same_bits(d_all, d_off));
  CHECK(same_bits(v_all, v_off));
}

TEST_CASE("bad input: a self pair without the model's rows, a body that does not exist, surfaces not chains") {
  const std::vector<vec2> X{vec2(0.0, 0.0), vec2(1.0, 0.0)};
  const std::vector<double> m{1.0, 1.0};
  contact::body_contact self({contact::body_pair{0, 0}});
  const std::string rows = test::error_message([&] { self.setup(contact_body{X, m}, {}); });
  MESSAGE(rows);
  CHECK(test::contains(rows, "need the model's bodies and the shape functions at the particles"));
  contact::body_contact all(contact::all_body_pairs);
  CHECK(test::contains(test::error_message([&] { all.setup(contact_body{X, m}, {}); }), "shape functions"));

  // A self pair of body 1 in a problem of one body.
  const background_mesh mesh = ring_mesh();
  problem_for<plane_elastic<coulomb_t>> p{.particles = particles_from_mesh(mesh, 2.0),
                                          .mesh = mesh,
                                          .material = material::elastic({1e7, 0.3, 1000.0}),
                                          .contact = coulomb_t(plates(), {contact::body_pair{1, 1}})};
  run_options o;
  o.end_time = 1e-6;
  const std::string missing = test::error_message([&] { make_solver<plane_elastic<coulomb_t>>(std::move(p), o); });
  MESSAGE(missing);
  CHECK(test::contains(missing, "body 1 does not exist"));
  CHECK(std::count(missing.begin(), missing.end(), '\n') == 0);

  // Particles that are not the mesh nodes: no surface chains to be slaves and masters.
  const vec2 lo(0.0, 0.0), hi(4e-3, 2e-3);
  problem_for<plane_elastic<coulomb_t>> q{.particles = make_grid_particles<2>(lo, hi, Eigen::Vector2i(9, 5), 2.0),
                                          .mesh = make_grid_mesh(lo, hi, Eigen::Vector2i(5, 3)),
                                          .material = material::elastic({1e7, 0.3, 1000.0}),
                                          .contact = coulomb_t({}, contact::all_body_pairs),
                                          .slave_particles = {0}};
  const std::string chains = test::error_message([&] { make_solver<plane_elastic<coulomb_t>>(std::move(q), o); });
  MESSAGE(chains);
  CHECK(test::contains(chains, "surfaces are not chains of particles"));
}

}  // namespace test_numeric_self_contact
