// The force loop at every lane width users build (solver/point_force_loop.hpp): 2 lanes (x86-64's
// baseline, what this test build has), 4 (AVX2: tools/rkpm run and paper, RKPM_NATIVE_ARCH=SAME_BITS)
// and 8 (AVX-512), and the point-by-point update, all on the trajectory of a real run. The paper's
// Taylor bar (cases/taylor_bar.hpp, contact, J2, the impact face yielding) runs with the solver as
// built here; after every step the points are evaluated again at the run's coefficients with
// point_materials<G, M, simd_of<N>> for N = 2, 4, 8 and with a material that takes no lanes, each
// advancing its own states, and f_int, every point's state, the narrowest stretch and the plastic
// work must have the solver's bits. The step reads nothing else of the points, so a run at any of
// these widths takes the same steps to the same bits: this is the byte-for-byte comparison of the
// SAME_BITS runner with the baseline one, made a test. simd_of<N> is std::experimental's
// fixed-size vector, which the compiler splits over the registers of this build's flags (no
// AVX2 needed), with the same IEEE +, -, *, / and sqrt per lane.
// Q2 and Q4 (paired rows: two and four points per table row), and the re-referenced force terms
// (docs/method.md (79)-(80)) after the solver's rereference().
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/taylor_bar.hpp"

namespace lane_widths_test {

using namespace rkpm;

using tb = cases::taylor_bar;
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using G = tb::geometry_type;
using M = tb::material_type;

// The same J2 law, whose bodies say they take no lanes (updates_in_lanes): the force loop
// updates every point by the scalar code.
struct one_by_one : M {
  explicit one_by_one(const M& m) : M(m) {}
};
constexpr bool updates_in_lanes(const one_by_one&) { return false; }

// The same bits, unless Eigen's 2x2 products fuse multiply-adds (tests built with
// RKPM_NATIVE_ARCH=ON on a machine with FMA units): the lanes never fuse (-ffp-contract=off),
// the point-by-point form then does, and the results move apart by rounding, each value within
// a relative 1e-9 of the run's (a few steps of rounding differences that the states carry on).
// tools/rkpm test builds without -march: bit for bit.
#ifdef EIGEN_VECTORIZE_FMA
constexpr double tolerance = 1e-9;
#else
constexpr double tolerance = 0.0;
#endif
bool same(double a, double b) {
  if constexpr (tolerance == 0.0) return std::memcmp(&a, &b, sizeof a) == 0;
  return std::abs(a - b) <= tolerance * std::max(std::abs(a), std::abs(b)) || std::abs(a - b) < 1e-290;
}
// Vectors of doubles or of aggregates of doubles (vec2, j2_state), value by value.
template <class T>
bool same(const std::vector<T>& a, const std::vector<T>& b) {
  static_assert(sizeof(T) % sizeof(double) == 0);
  if (a.size() != b.size()) return false;
  if constexpr (tolerance == 0.0) return std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
  const std::size_t n = a.size() * sizeof(T) / sizeof(double);
  for (std::size_t i = 0; i < n; ++i) {
    double x, y;
    std::memcpy(&x, reinterpret_cast<const char*>(a.data()) + i * sizeof(double), sizeof x);
    std::memcpy(&y, reinterpret_cast<const char*>(b.data()) + i * sizeof(double), sizeof y);
    if (!same(x, y)) return false;
  }
  return true;
}

// One width's points, following the solver's model.
template <class Material, class V>
struct points_at {
  materials_by_body<Material> material;
  point_materials<G, Material, V> points;
  std::vector<vec2> f;

  explicit points_at(const discrete_model& m, const M& law)
      : material(m, Material(law), {}), points(m, material), f(m.particle_count()) {}

  template <class Solver>
  void check(const char* width, const Solver& s, step_context where) {
    points.internal_force(s.model(), material, s.coefficients(), f, where);
    INFO(width);
    CHECK(same(f, s.internal_force()));
    CHECK(same(points.states(), s.point_states()));
    CHECK(same(points.min_stretch(), s.min_stretch()));
    CHECK(same(points.plastic_work(), s.energy().plastic));
  }
};

template <class Quadrature>
void check_widths(int steps, int rereference_every) {
  using cfg = config<kernel::cubic_spline, correction::linear, Quadrature, G, M, contact_t>;
  tb::parameters p;
  run_options o;
  o.end_time = p.end_time_s;
  auto s = make_solver<cfg>(tb::build<contact_t>(p, 1), o);
  REQUIRE(s.model().traversal.paired_rows);
  static_assert(point_materials<G, M, simd_of<4>>::batched);
  REQUIRE(!updates_in_lanes(one_by_one(s.material())));  // lane_widths_test's, not J2's

  points_at<one_by_one, simd_double> scalar(s.model(), s.material());
  points_at<M, simd_of<2>> two(s.model(), s.material());
  points_at<M, simd_of<4>> four(s.model(), s.material());
  points_at<M, simd_of<8>> eight(s.model(), s.material());
  const auto check_all = [&](step_context where) {
    scalar.check("point by point", s, where);
    two.check("2 lanes", s, where);
    four.check("4 lanes", s, where);
    eight.check("8 lanes", s, where);
  };
  check_all({0, 0.0, 0.0});  // the set-up's evaluation at d = 0
  discrete_model reference = s.model();
  for (int n = 1; n <= steps; ++n) {
    const double dt = s.time_step();
    s.step();
    CAPTURE(n);
    check_all({s.steps(), s.time(), dt});
    if (rereference_every > 0 && n % rereference_every == 0) {
      s.rereference();  // the points at the new reference, evaluated again at d = 0
      scalar.points.rereference(reference, s.model());
      two.points.rereference(reference, s.model());
      four.points.rereference(reference, s.model());
      eight.points.rereference(reference, s.model());
      reference = s.model();
      check_all({s.steps(), s.time(), 0.0});
    }
  }
  // The run reached what the lanes must agree on: yielding points (a return in some lanes of a
  // batch, not in others) and, re-referenced, the (80) terms.
  int yielded = 0;
  for (const auto& state : s.point_states()) yielded += state.equivalent_plastic_strain > 0.0;
  CHECK(yielded > 0);
  CHECK(yielded < s.model().point_count());
  CHECK(s.rereferences() == (rereference_every > 0 ? steps / rereference_every : 0));
}

TEST_CASE("lane widths: 2, 4 and 8 lanes and point by point give the Q2 Taylor bar's bits") {
  check_widths<quadrature::q2>(40, 0);
}

TEST_CASE("lane widths: 2, 4 and 8 lanes and point by point give the Q4 Taylor bar's bits") {
  check_widths<quadrature::q4>(25, 0);
}

TEST_CASE("lane widths: re-referenced, every width keeps the run's bits") {
  check_widths<quadrature::q2>(30, 10);
}

}  // namespace lane_widths_test
