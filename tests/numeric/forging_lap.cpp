// A forging lap (contact/body_contact.hpp in all-pairs mode; docs/method.md section 6.11): a steel
// block with a slot cut into one side is upset between two flat dies with Coulomb friction. The
// slot's faces fold towards each other and meet, as the surface of a forging folds onto itself
// where a lap forms. With `all_body_pairs` (no pair declared) the faces touch and stay apart: no
// particle of one face goes through the other face (measured from the particles' positions, not
// from the contact's report) by more than 2% of the spacing, and the dies push harder than
// without, where the faces pass through each other by several spacings. At two resolutions the
// faces first touch at about the same reduction of the height. Plane strain, J2 with linear
// hardening, the paper's contact (a solver of include/rkpm/solver/solver_instances.hpp, so the
// file instantiates no solver of its own).

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/discretization/mesh_particles.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/solver/make_solver.hpp>

namespace test_numeric_forging_lap {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using coulomb_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using method = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                      material::j2_plasticity<material::hardening::linear>, coulomb_t>;

// The block: 10 x 8 mm, `n` cells across (spacing h = 10 mm / n), the slot 4 mm deep (0.4 of the
// width) and 2 mm high (a quarter of the height), at mid-height on the right. The slot's height (2 mm) is twice the kernels' reach (support factor 2), so its faces
// are no kernel neighbours and self-contact sees them (108).
constexpr double width = 10e-3, height = 8e-3, die_speed = 5.0, reduction = 0.4;

struct upset {
  double h = 0.0;
  double deepest = 0.0;          // deepest face particle through the other face, / h
  double touch_reduction = -1.0; // height reduction at the first self-contact
  double end_force = 0.0;        // the top die's mean force over the last 5% of the run, N/m
};

upset upset_block(int n, bool self) {
  const int nx = n, ny = 4 * n / 5, slot_rows = ny / 4, slot_columns = 2 * nx / 5;
  const double h = width / nx;
  const background_mesh grid = make_grid_mesh(vec2(0, 0), vec2(width, height), Eigen::Vector2i(nx + 1, ny + 1));
  // The grid less the slot's cells, its nodes numbered anew (grid node (i, j) is j (nx + 1) + i).
  background_mesh mesh;
  std::vector<stored_index> node_of(grid.node.size(), -1);
  const int row0 = ny / 2 - slot_rows / 2, row1 = row0 + slot_rows;
  for (index_t c = 0; c < grid.cells(); ++c) {
    const int i = static_cast<int>(c % nx), j = static_cast<int>(c / nx);
    if (j >= row0 && j < row1 && i >= nx - slot_columns) continue;
    std::array<stored_index, 4> cell{};
    for (int k = 0; k < 4; ++k) {
      stored_index& id = node_of[grid.cell[c][k]];
      if (id < 0) {
        id = static_cast<stored_index>(mesh.node.size());
        mesh.node.push_back(grid.node[grid.cell[c][k]]);
      }
      cell[k] = id;
    }
    mesh.cell.push_back(cell);
  }
  std::vector<index_t> lower, upper;  // the slot's faces, x increasing
  for (int i = nx - slot_columns; i <= nx; ++i) {
    lower.push_back(node_of[row0 * (nx + 1) + i]);
    upper.push_back(node_of[row1 * (nx + 1) + i]);
  }

  using contact::rigid_tool;
  std::vector<rigid_tool> dies{rigid_tool("top", {vec2(3 * width, height), vec2(-2 * width, height)}, contact::side::left,
                                          contact::tool_motion::constant_velocity(vec2(0.0, -die_speed)), 0.5 * h),
                               rigid_tool("bottom", {vec2(-2 * width, 0.0), vec2(3 * width, 0.0)}, contact::side::left,
                                          contact::tool_motion::constant_velocity(vec2(0.0, die_speed)), 0.5 * h)};
  const contact::friction::coulomb friction{0.3};
  problem_for<method> p{
      .particles = particles_from_mesh(mesh, 2.0),
      .mesh = mesh,
      .material = material::j2_plasticity<material::hardening::linear>({200e9, 0.3, 7800.0}, {300e6, 1e9}),
      .contact = self ? coulomb_t(std::move(dies), contact::all_body_pairs, friction) : coulomb_t(std::move(dies), friction)};
  run_options o;
  o.end_time = reduction * height / (2.0 * die_speed);
  auto s = make_solver<method>(std::move(p), o);

  // How far particle P has gone through a face (a chain, x increasing): the face's height at P's
  // x, interpolated, less P's (`from_above`: P came from above the face), positive when through.
  const auto through = [](const std::vector<vec2>& x, const vec2& P, const std::vector<index_t>& face, bool from_above) {
    double worst = 0.0;
    for (std::size_t k = 0; k + 1 < face.size(); ++k) {
      const vec2& a = x[face[k]];
      const vec2& b = x[face[k + 1]];
      if (P[0] < std::min(a[0], b[0]) || P[0] > std::max(a[0], b[0]) || a[0] == b[0]) continue;
      const double y = a[1] + (b[1] - a[1]) * (P[0] - a[0]) / (b[0] - a[0]);
      worst = std::max(worst, from_above ? y - P[1] : P[1] - y);
    }
    return worst;
  };
  upset r;
  r.h = h;
  std::vector<double> time, impulse;
  while (s.time() < o.end_time * (1.0 - 1e-12)) {
    s.step();
    time.push_back(s.time());
    impulse.push_back(s.tool_impulses()[0][1]);
    if (r.touch_reduction < 0.0 && !s.contact().bodies().active_pairs().empty())
      r.touch_reduction = 2.0 * die_speed * s.time() / height;
    const std::vector<vec2> x = s.particle_positions();
    for (std::size_t k = 1; k + 1 < upper.size(); ++k) {  // the faces' inner particles (not the root or the mouth)
      r.deepest = std::max(r.deepest, through(x, x[upper[k]], lower, true) / h);
      r.deepest = std::max(r.deepest, through(x, x[lower[k]], upper, false) / h);
    }
  }
  const std::size_t last = time.size() - 1, from = static_cast<std::size_t>(0.95 * static_cast<double>(last));
  r.end_force = (impulse[last] - impulse[from]) / (time[last] - time[from]);
  return r;
}

}  // namespace

TEST_CASE("a forging lap: a slotted block upset between dies folds its slot shut, and its faces stay apart") {
  const upset coarse = upset_block(20, true), coarse_off = upset_block(20, false), fine = upset_block(30, true);
  MESSAGE("slot faces first touch at a height reduction of " << coarse.touch_reduction << " (h = " << coarse.h * 1e3
          << " mm) and " << fine.touch_reduction << " (h = " << fine.h * 1e3 << " mm); deepest face particle through "
          << "the other face: " << coarse.deepest << " h and " << fine.deepest << " h with self-contact, "
          << coarse_off.deepest << " h without; top die force at the end " << coarse.end_force << " N/m, "
          << coarse_off.end_force << " N/m without");
  CHECK(coarse.touch_reduction > 0.15);
  CHECK(coarse.touch_reduction < 0.3);
  CHECK(fine.touch_reduction == doctest::Approx(coarse.touch_reduction).epsilon(0.1));
  CHECK(coarse.deepest < 0.02);
  CHECK(fine.deepest < 0.02);
  CHECK(coarse_off.deepest > 1.0);  // the test can fail: without self-contact the faces cross
  CHECK(coarse.end_force > 1.05 * coarse_off.end_force);
}

}  // namespace test_numeric_forging_lap
