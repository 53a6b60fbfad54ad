// Fracture (material/rankine_fracture.hpp, solver/crack_growth.hpp; docs/method.md sections 3.7,
// 4.7 and 5.12), against conservation laws and the fracture energy:
//  - a brittle bar whose halves are thrown apart (the left half at -V, the right at +V, so that
//    the tension is largest at the middle from the start) breaks there: two pieces, the total
//    linear momentum kept to round-off at every step, and once the crack has opened each piece
//    keeps its momentum (no force crosses the crack) to round-off; the energy dissipated is the
//    fracture energy G_c times the crack's length H within 10%, at two resolutions (with the
//    band h = a of an earlier choice it was 26% short: the test can fail), and the ledger (its
//    remap term included) balances;
//  - an edge-notched plate pulled slowly in mode I: the crack runs straight across the ligament,
//    the plate ends in two pieces, the mean force on the pulled edge falls to zero, and the energy
//    dissipated is G_c times the ligament within 15% at 15 cells of ligament and 10% at 30 (the
//    error halving with the spacing, docs/method.md section 4.7);
//  - a run continued from a checkpoint written while the crack grows is the uninterrupted run, bit
//    for bit (the cuts are in the checkpoint, the model rebuilt from them);
//  - a particle that cracks cut off alone becomes a free particle (its own row, its own volume),
//    not a singular moment matrix;
//  - the snapshot of the broken bar draws the crack open: each cut cell as its two sides, whose
//    crack points, with coefficients linear on each side (different on the two), sit where the
//    field of their own side puts them to round-off; in the run, the right side's points right
//    of the left side's; every failed point a vertex of its own;
//  - a Johnson-Cook bar whose halves are thrown apart, with damage that opens cracks (32f), fails
//    in tension at the middle and breaks in two, with its total momentum kept to round-off; with
//    the damage alone (no opens_cracks) its failed points carry no tension but the kernels still
//    join the halves: one piece, and no cell cut;
//  - the same bar eight cells thick, whose band of failed cells is several cells wide, is cut
//    once across it, not in every cell (beside_a_cut): two pieces, neither a sliver, and the
//    stable step above a tenth of the first (with every failed cell cut: 0.0036).

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include <rkpm/io/crack_snapshot.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/material/rankine_fracture.hpp>
#include <rkpm/solver/checkpoint.hpp>
#include <rkpm/solver/make_model.hpp>

#include "support/solver_fixtures.hpp"

namespace test_numeric_fracture {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

// A PMMA-like brittle solid with Poisson's ratio 0 (the bar is 1D: wave speed sqrt(E / rho)); the
// plate is stronger, so that it is larger than the characteristic length E G_c / sigma_t^2 and the
// crack runs from the notch before the ligament softens everywhere.
constexpr double E = 3e9, rho = 1180.0, sigma_t = 10e6, G_c = 500.0, plate_strength = 30e6;
constexpr double L = 20e-3, H = 4e-3;
// The halves' speed: the stress rho c V at the middle exceeds sigma_t from the start.
constexpr double V = 10.0;
const double c = std::sqrt(E / rho);

using brittle = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                       material::rankine_fracture, contact::none>;

struct broken_bar {
  index_t pieces = 0;
  double dissipated = 0.0;            // J/m (per unit thickness)
  double worst_total_momentum = 0.0;  // max |P(t) - P(0)| over the steps / (m V)
  double piece_momentum_drift = 0.0;  // max |P_piece(t) - P_piece(t_open)| after the crack opened / (m V)
  double opened_at = -1.0;            // s, when the model first held two pieces
  double balance_error = 0.0;
  index_t cuts = 0;
};

solver_for<brittle> thrown_bar(double h) {
  const Eigen::Vector2i n(static_cast<int>(std::lround(L / h)) + 1, static_cast<int>(std::lround(H / h)) + 1);
  const vec2 lo(0.0, 0.0), hi(L, H);
  const double support = 2.0 * h;
  problem_for<brittle> p{
      .particles = make_grid_particles<2>(lo, hi, n, 2.0),
      .mesh = make_grid_mesh(lo, hi, n),
      .material = material::rankine_fracture({E, 0.0, rho}, sigma_t, G_c,
                                             material::rankine_fracture::band_width_of_support<kernel::cubic_spline>(support)),
      .contact = {}};
  // The middle column of particles goes with the left half: the jump, and the crack, lie in the
  // cells just right of it.
  p.initial_particle_velocity = [](index_t, const vec2& X) { return vec2(X[0] <= 0.5 * L + 1e-9 ? -V : V, 0.0); };
  run_options o;
  o.end_time = 3.0 * L / c;
  return make_solver<brittle>(std::move(p), o);
}

broken_bar break_bar(double h) {
  auto s = thrown_bar(h);

  double m = 0.0;
  for (double mI : s.mass()) m += mI;
  const auto momentum = [&](auto&& in_piece) {
    vec2 P = vec2::Zero();
    for (index_t I = 0; I < s.model().particle_count(); ++I)
      if (in_piece(s.initial_positions()[I])) P += s.mass()[I] * s.coefficient_velocities()[I];
    return P;
  };
  const auto left = [](const vec2& X) { return X[0] <= 0.5 * L + 1e-9; };
  const auto right = [&](const vec2& X) { return !left(X); };
  broken_bar out;
  vec2 left_at_open = vec2::Zero(), right_at_open = vec2::Zero();
  const auto total = [&] { return momentum([](const vec2&) { return true; }); };
  const vec2 P0 = total();  // (m_left - m_right) V: the middle column goes left
  while (s.before_end()) {
    s.step_to_end();
    out.worst_total_momentum = std::max(out.worst_total_momentum, (total() - P0).norm() / (m * V));
    if (out.opened_at < 0.0 && s.fragments().pieces == 2) {
      out.opened_at = s.time();
      left_at_open = momentum(left);
      right_at_open = momentum(right);
    } else if (out.opened_at >= 0.0) {
      out.piece_momentum_drift = std::max({out.piece_momentum_drift, (momentum(left) - left_at_open).norm() / (m * V),
                                           (momentum(right) - right_at_open).norm() / (m * V)});
    }
  }
  out.pieces = s.fragments().pieces;
  out.dissipated = s.energy().plastic;
  out.balance_error = s.energy().balance_error();
  out.cuts = static_cast<index_t>(s.cracks().size());
  MESSAGE("h = " << h << ": " << out.cuts << " cells cut, two pieces at t = " << out.opened_at
                 << " s, dissipated " << out.dissipated << " J/m against G_c H = " << G_c * H << ", momentum drift "
                 << out.piece_momentum_drift << ", balance " << out.balance_error);
  return out;
}

}  // namespace

TEST_CASE("fracture: a brittle bar thrown apart breaks in two, keeps its momentum and dissipates G_c H") {
  REQUIRE(rho * c * V > sigma_t);
  for (const double h : {0.5e-3, 0.25e-3}) {
    CAPTURE(h);
    const broken_bar b = break_bar(h);
    CHECK(b.pieces == 2);
    CHECK(b.opened_at > 0.0);
    CHECK(b.worst_total_momentum < 1e-12);
    CHECK(b.piece_momentum_drift < 1e-10);
    CHECK(b.dissipated == doctest::Approx(G_c * H).epsilon(0.10));
    CHECK(b.balance_error < 0.02);
  }
}

TEST_CASE("fracture: the snapshot draws each cut cell as its two sides, its crack points on their own side") {
  const double h = 1e-3;
  auto s = thrown_bar(h);
  while (s.before_end()) s.step_to_end();
  const discrete_model& m = s.model();
  const std::vector<cell_crack>& cuts = s.cracks();
  REQUIRE(s.fragments().pieces == 2);
  REQUIRE(!cuts.empty());
  const auto n = static_cast<std::size_t>(m.particle_count());
  const auto left = [&](index_t I) { return s.initial_positions()[I][0] <= 0.5 * L + 1e-9; };

  // Coefficients linear on each side, a different field on each: the approximation reproduces
  // each side's field there (its kernels do not reach across), and so must the crack points.
  const mat2 G_left{{0.01, -0.02}, {0.03, 0.005}}, G_right{{-0.04, 0.01}, {0.02, -0.03}};
  const vec2 a_left(1e-4, -2e-4), a_right(3e-4, 5e-5);
  const auto field = [&](bool on_left, const vec2& X) -> vec2 {
    return on_left ? (a_left + G_left * X).eval() : (a_right + G_right * X).eval();
  };
  std::vector<vec2> d(n);
  for (index_t I = 0; I < m.particle_count(); ++I) d[I] = field(left(I), m.particles.position[I]);
  const io::crack_faces linear = io::crack_face_points(m, cuts, d);
  REQUIRE(linear.position.size() == 4 * cuts.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < linear.position.size(); ++k) {
    const cell_crack& cut = cuts[k / 4];
    const int e = (k % 4 == 0 || k % 4 == 3) ? 0 : 1;  // the crossing's cell side (crack_snapshot.hpp's order)
    const auto& corner = m.mesh.cell[cut.cell];
    const vec2 X_c = (1.0 - cut.at[e]) * m.particles.position[corner[cut.side[e]]] +
                     cut.at[e] * m.particles.position[corner[(cut.side[e] + 1) % 4]];
    const vec2 expected = X_c + field(left(linear.corner[k]), X_c);
    worst = std::max(worst, (linear.position[k] - expected).norm());
  }
  MESSAGE(cuts.size() << " cells cut; crack points off their side's linear field by " << worst << " m");
  CHECK(worst < 1e-12 * L);

  // The run's own snapshot.
  const io::snapshot_extras extras = io::snapshot_extras_of(s);
  index_t failed = 0;
  for (const auto& state : s.point_states()) failed += state.failed() ? 1 : 0;
  std::size_t faces = 0, failed_points = 0, quads = 0, polygons = 0;
  for (const std::uint8_t k : extras.kind) (k == io::point_kind_crack_face ? faces : failed_points) += 1;
  CHECK(faces == 4 * cuts.size());
  CHECK(failed_points == static_cast<std::size_t>(failed));
  for (std::size_t c = 0; c < extras.cells.size(); ++c) {
    const std::int64_t begin = c == 0 ? 0 : extras.cells.offsets[c - 1];
    if (extras.cells.types[c] == io::vtk_quad) ++quads;
    if (extras.cells.types[c] != io::vtk_polygon) continue;
    ++polygons;
    int sides_seen = 0;  // a polygon's particles lie on one side of the crack
    for (std::int64_t k = begin; k < extras.cells.offsets[c]; ++k) {
      const std::int64_t p = extras.cells.connectivity[static_cast<std::size_t>(k)];
      if (p < static_cast<std::int64_t>(n)) sides_seen |= left(static_cast<index_t>(p)) ? 1 : 2;
    }
    CHECK(extras.cells.offsets[c] - begin >= 3);
    CHECK((sides_seen == 1 || sides_seen == 2));
  }
  CHECK(polygons == 2 * cuts.size());
  CHECK(quads + cuts.size() == static_cast<std::size_t>(m.mesh.cells()));
  // The crack is open: at each crossing the right side's point lies right of the left side's.
  for (std::size_t cut = 0; cut < cuts.size(); ++cut)
    for (const auto& [first, second] : {std::pair{4 * cut, 4 * cut + 3}, std::pair{4 * cut + 1, 4 * cut + 2}}) {
      const bool first_left = left(extras.source[first]);
      CHECK(first_left != left(extras.source[second]));
      const double gap = first_left ? extras.position[second][0] - extras.position[first][0]
                                    : extras.position[first][0] - extras.position[second][0];
      CHECK(gap > 0.01 * h);
    }

  // Written: every point array on the extras too, and the cells valid on them.
  const auto file = std::filesystem::temp_directory_path() / "rkpm_fracture_snapshot.vtu";
  io::snapshot_parts parts = io::snapshot_of(s);
  CHECK(parts.points == n + extras.position.size());
  io::vtu_format text;
  text.encoding = io::vtu_encoding::ascii;
  io::write_vtu(file, parts.points, parts.xyz, parts.cells, parts.fields, text);
  std::vector<vec2> points(parts.points);
  const auto xyz = io::filled_values<double>(3 * parts.points, parts.xyz);
  for (std::size_t k = 0; k < parts.points; ++k) points[k] = vec2(xyz[3 * k], xyz[3 * k + 1]);
  CHECK_NOTHROW(io::write_vtu(file, points, io::cells_of(parts.cells), parts.fields));
  std::filesystem::remove(file);
}

namespace {

struct notched_plate {
  double ligament = 0.0;         // m, the crack's length to cross
  double crack_reach = 0.0;      // m, the furthest cut cell's centre
  double peak_reaction = 0.0;    // N/m on the pulled edge
  double final_reaction = 0.0;   // N/m, its mean over the last 40% of the run
  double dissipated = 0.0;       // J/m
  double balance_error = 0.0;
  index_t pieces = 0;
};

// A square plate W x W with an edge notch of length W/4 at mid-height (cells cut before the
// run, as a crack cuts them), its top and bottom edges pulled apart at +-V (reached over a
// tenth of the run): mode I.
constexpr double W = 10e-3, speed = 0.5;

// The plate with its notch cut; `top`: the particles of its pulled upper edge.
solver_for<brittle> notched_plate_solver(double h, std::vector<index_t>& top, double& ligament) {
  const int n = static_cast<int>(std::lround(W / h)) + 1;
  const vec2 lo(0.0, 0.0), hi(W, W);
  problem_for<brittle> p{.particles = make_grid_particles<2>(lo, hi, Eigen::Vector2i(n, n), 2.0),
                         .mesh = make_grid_mesh(lo, hi, Eigen::Vector2i(n, n)),
                         .material = material::rankine_fracture({E, 0.0, rho}, plate_strength, G_c,
                                                                material::rankine_fracture::band_width_of_support<kernel::cubic_spline>(2.0 * h)),
                         .contact = {}};
  // Twice the time the edges take to open the elastic strain and the crack's full opening
  // 2 G_c / sigma_t (the linear softening's).
  const double end = 2.0 * ((plate_strength / E) * W + 2.0 * G_c / plate_strength) / (2.0 * speed), ramp = 0.1 * end;
  top.clear();
  for (index_t I = 0; I < p.particles.size(); ++I) {
    const double y = p.particles.position[I][1];
    const double sign = y > W - 1e-9 ? 1.0 : y < 1e-9 ? -1.0 : 0.0;
    if (sign == 0.0) continue;
    p.constraints.push_back({I, 1, [=](double t) { return sign * speed * std::min(1.0, t / ramp); }});
    if (sign > 0.0) top.push_back(I);
  }
  run_options o;
  o.end_time = end;
  auto s = make_solver<brittle>(std::move(p), o);
  // The notch: the cells of the row just below mid-height, from the left edge to W / 4.
  const index_t row = (n - 1) / 2 - 1;
  std::vector<std::pair<index_t, vec2>> notch;
  for (index_t i = 0; i * h < 0.25 * W - 1e-9; ++i) notch.emplace_back(row * (n - 1) + i, vec2(0.0, 1.0));
  s.cut_cells(notch);
  ligament = W - static_cast<double>(notch.size()) * h;
  return s;
}

notched_plate pull_notched_plate(double h) {
  notched_plate out;
  std::vector<index_t> top;
  auto s = notched_plate_solver(h, top, out.ligament);
  const double end = s.options().end_time;
  const auto reaction = [&] {
    double f = 0.0;
    for (index_t I : top) f += s.internal_force()[I][1];
    return f;
  };
  // The mean reaction over the last 40% of the run: the separated half rings, its mean force is zero.
  double late_impulse = 0.0;
  while (s.before_end()) {
    s.step_to_end();
    out.peak_reaction = std::max(out.peak_reaction, reaction());
    if (s.time() > 0.6 * end) late_impulse += reaction() * s.time_step();
  }
  out.final_reaction = late_impulse / (0.4 * end);
  for (const cell_crack& k : s.cracks()) {
    vec2 centre = vec2::Zero();
    for (const stored_index c : s.model().mesh.cell[k.cell]) centre += 0.25 * s.initial_positions()[c];
    out.crack_reach = std::max(out.crack_reach, centre[0]);
  }
  out.dissipated = s.energy().plastic;
  out.balance_error = s.energy().balance_error();
  out.pieces = s.fragments().pieces;
  MESSAGE("notched plate, h = " << h << ": " << s.cracks().size() << " cells cut, reach " << out.crack_reach
                                << ", reaction " << out.peak_reaction << " -> " << out.final_reaction << " N/m, dissipated "
                                << out.dissipated << " J/m against G_c x ligament = " << G_c * out.ligament
                                << ", balance " << out.balance_error);
  return out;
}

}  // namespace

TEST_CASE("fracture: a notched plate pulled in mode I breaks across, and then no force passes") {
  std::vector<double> error;
  for (const double h : {0.5e-3, 0.25e-3}) {
    CAPTURE(h);
    const notched_plate b = pull_notched_plate(h);
    CHECK(b.pieces == 2);
    CHECK(b.crack_reach > 10e-3 - h);  // the last cell's centre: across
    CHECK(std::abs(b.final_reaction) < 0.01 * b.peak_reaction);
    CHECK(b.balance_error < 0.02);
    error.push_back(std::abs(b.dissipated / (G_c * b.ligament) - 1.0));
  }
  CHECK(error[0] < 0.15);
  CHECK(error[1] < 0.10);
  CHECK(error[1] < 0.75 * error[0]);
}

TEST_CASE("fracture across a checkpoint: the run continued from it is the uninterrupted one, bit for bit") {
  std::vector<index_t> top;
  double ligament = 0.0;
  auto whole = notched_plate_solver(0.5e-3, top, ligament);
  const index_t notch = static_cast<index_t>(whole.cracks().size());
  whole.run();
  auto first = notched_plate_solver(0.5e-3, top, ligament);
  while (static_cast<index_t>(first.cracks().size()) < notch + 4) first.step_to_end();  // the crack a third across
  const auto path = std::filesystem::temp_directory_path() / "rkpm_fracture_restart.rkpmcp";
  write_checkpoint(first, path, brittle::name());
  auto second = notched_plate_solver(0.5e-3, top, ligament);
  read_checkpoint(second, path, brittle::name());
  std::filesystem::remove(path);
  REQUIRE(second.cracks().size() == first.cracks().size());
  second.run();
  CHECK(whole.cracks().size() > first.cracks().size());
  CHECK(second.steps() == whole.steps());
  CHECK(second.cracks().size() == whole.cracks().size());
  CHECK(second.coefficients() == whole.coefficients());
  CHECK(second.energy().plastic == whole.energy().plastic);
  CHECK(second.fragments().pieces == 2);
}

TEST_CASE("fracture: a particle cut off alone by cracks is a free particle") {
  const Eigen::Vector2i n(6, 6);
  particle_set<2> particles = make_grid_particles<2>(vec2(0, 0), vec2(0.5, 0.5), n, 2.0);
  background_mesh cells = make_grid_mesh(vec2(0, 0), vec2(0.5, 0.5), n);
  // Two cracks box in the corner particle (0, 0) and the quadrature points next to it.
  // (They cross past the corner: two segments that only meet leave a sight line through the point.)
  cells.cracks = crack_set({{vec2(0.06, -0.1), vec2(0.06, 0.07)}, {vec2(-0.1, 0.06), vec2(0.07, 0.06)}});
  const discrete_model m = make_model<geometry::plane_strain>(method_names{"cubic", "linear", "q4"}, particles, cells,
                                                              default_max_moment_condition);
  REQUIRE(m.at_particles.offset[1] - m.at_particles.offset[0] == 1);
  CHECK(m.at_particles.neighbor[0] == 0);
  CHECK(m.at_particles.N[0] == 1.0);
  CHECK(m.lumped_volume[0] == doctest::Approx(particles.volume[0]));
  CHECK(crack_fragments(m, lumped_masses(m, 1.0)).pieces == 2);
}

namespace {

using ductile = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                       material::johnson_cook, contact::none>;

struct pulled_bar {
  index_t pieces = 0;
  index_t cuts = 0;
  index_t failed = 0;                   // failed points at the end
  double worst_total_momentum = 0.0;    // max |P(t) - P(0)| over the steps / (m V)
  double largest_mass_fraction = 0.0;   // the largest piece's mass / the bar's
  double smallest_step = 0.0;           // the smallest stable step over the first
  double smallest_piece_fraction = 0.0; // of two pieces, the smaller one's mass / the bar's (else 0)
};

// A steel-like bar, as long as the brittle one and two cells thick, its halves thrown apart at V:
// the jump flows plastically and necks at the middle until the failure strain (D1 = 0.1, eps_f
// constant) is reached there, in tension.
pulled_bar pull_johnson_cook_bar(bool opens_cracks, int cells_thick = 2) {
  constexpr double steel_V = 50.0, h = 0.5e-3;
  const double thickness = cells_thick * h;
  const Eigen::Vector2i n(static_cast<int>(std::lround(L / h)) + 1, static_cast<int>(std::lround(thickness / h)) + 1);
  const vec2 lo(0.0, 0.0), hi(L, thickness);
  material::johnson_cook_damage damage{0.1, 0.0, 0.0, 0.0, 0.0};
  damage.opens_cracks = opens_cracks;
  problem_for<ductile> p{
      .particles = make_grid_particles<2>(lo, hi, n, 2.0),
      .mesh = make_grid_mesh(lo, hi, n),
      .material = material::johnson_cook({200e9, 0.3, 7800.0},
                                         material::hardening::johnson_cook{300e6, 100e6, 0.3, 0.0, 1.0, 1.0, 294.0, 1800.0},
                                         material::johnson_cook_heating{460.0}, damage),
      .contact = {}};
  p.initial_particle_velocity = [](index_t, const vec2& X) { return vec2(X[0] <= 0.5 * L + 1e-9 ? -steel_V : steel_V, 0.0); };
  run_options o;
  o.end_time = 8e-6;
  auto s = make_solver<ductile>(std::move(p), o);
  double m = 0.0;
  for (double mI : s.mass()) m += mI;
  const auto total = [&] {
    vec2 P = vec2::Zero();
    for (index_t I = 0; I < s.model().particle_count(); ++I) P += s.mass()[I] * s.coefficient_velocities()[I];
    return P;
  };
  const vec2 P0 = total();
  pulled_bar out;
  const double first_step = s.time_step();
  out.smallest_step = 1.0;
  while (s.before_end()) {
    s.step_to_end();
    out.worst_total_momentum = std::max(out.worst_total_momentum, (total() - P0).norm() / (m * steel_V));
    out.smallest_step = std::min(out.smallest_step, s.time_step() / first_step);
  }
  const fragment_count pieces = s.fragments();
  out.pieces = pieces.pieces;
  out.largest_mass_fraction = pieces.largest_mass / m;
  out.smallest_piece_fraction = pieces.pieces == 2 ? 1.0 - out.largest_mass_fraction : 0.0;  // of two pieces
  out.cuts = static_cast<index_t>(s.cracks().size());
  for (const auto& state : s.point_states()) out.failed += state.failed() ? 1 : 0;
  MESSAGE("Johnson-Cook bar, opens_cracks " << opens_cracks << ": " << out.failed << " failed points, " << out.cuts
                                            << " cells cut, " << out.pieces << " pieces (the largest "
                                            << out.largest_mass_fraction << " of the mass), momentum drift "
                                            << out.worst_total_momentum << ", " << s.steps()
                                            << " steps, smallest step / first " << out.smallest_step
                                            << ", smallest piece " << out.smallest_piece_fraction);
  return out;
}

}  // namespace

TEST_CASE("fracture: a cut made before the run is drawn open though the material opens none") {
  // A Johnson-Cook bar whose damage opens no cracks (cracks_can_grow() is false), one cell cut by
  // hand across its middle, as a notch is: the snapshot draws that cell as its two sides.
  constexpr double h = 0.5e-3;
  const Eigen::Vector2i n(static_cast<int>(std::lround(L / h)) + 1, 3);
  problem_for<ductile> p{
      .particles = make_grid_particles<2>(vec2(0, 0), vec2(L, 2 * h), n, 2.0),
      .mesh = make_grid_mesh(vec2(0, 0), vec2(L, 2 * h), n),
      .material = material::johnson_cook({200e9, 0.3, 7800.0},
                                         material::hardening::johnson_cook{300e6, 100e6, 0.3, 0.0, 1.0, 1.0, 294.0, 1800.0},
                                         material::johnson_cook_heating{460.0}, material::johnson_cook_damage{0.1, 0.0, 0.0, 0.0, 0.0}),
      .contact = {}};
  run_options o;
  o.end_time = 1e-7;
  auto s = make_solver<ductile>(std::move(p), o);
  REQUIRE(!s.cracks_can_grow());
  CHECK(io::snapshot_extras_of(s).empty());  // nothing cut: the plain snapshot
  const auto middle = static_cast<index_t>((n[0] - 1) / 2);  // the bottom row's middle cell
  s.cut_cells({{middle, vec2(1.0, 0.0)}});
  REQUIRE(s.cracks().size() == 1);
  const io::snapshot_extras extras = io::snapshot_extras_of(s);
  std::size_t faces = 0, polygons = 0;
  for (const std::uint8_t k : extras.kind) faces += k == io::point_kind_crack_face ? 1 : 0;
  for (const std::uint8_t t : extras.cells.types) polygons += t == io::vtk_polygon ? 1 : 0;
  CHECK(faces == 4);
  CHECK(polygons == 2);
}

TEST_CASE("fracture: a Johnson-Cook bar pulled apart breaks in two only when its damage opens cracks") {
  const pulled_bar opened = pull_johnson_cook_bar(true);
  CHECK(opened.failed > 0);
  CHECK(opened.cuts > 0);
  CHECK(opened.pieces == 2);
  CHECK(opened.largest_mass_fraction < 0.75);
  CHECK(opened.worst_total_momentum < 1e-12);
  const pulled_bar joined = pull_johnson_cook_bar(false);
  CHECK(joined.failed > 0);
  CHECK(joined.cuts == 0);
  CHECK(joined.pieces == 1);
}

TEST_CASE("fracture: a thick Johnson-Cook bar breaks across its band of failed cells once, leaving no sliver") {
  const pulled_bar thick = pull_johnson_cook_bar(true, 8);
  CHECK(thick.pieces == 2);
  CHECK(thick.smallest_piece_fraction > 0.25);
  CHECK(thick.smallest_step > 0.1);
  CHECK(thick.worst_total_momentum < 1e-12);
}

}  // namespace test_numeric_fracture
