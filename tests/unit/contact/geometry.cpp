// Rigid tool geometry and the segment search: normals, penetration, max depth, the choice of
// segment at convex and concave corners, sliding across a vertex, and the grid search against a
// brute-force search over all segments, for a tool and for moving surfaces (body pairs). The
// wheel punch of docs/method.md section 10.3 (in mm; the geometry is scale-free) has both kinds
// of corner.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <ranges>
#include <utility>
#include <vector>

#include <rkpm/contact/rigid_tool.hpp>
#include <rkpm/contact/segment_grid.hpp>
#include <rkpm/contact/segment_search.hpp>
#include <rkpm/contact/surface_search.hpp>

using namespace rkpm;
using namespace rkpm::contact;

namespace {

rigid_tool punch(tool_motion motion = {}) {
  return rigid_tool("punch", {{0, 38}, {10, 38}, {12, 28}, {24, 28}, {26, 38}, {34.5, 38}}, side::right,
                    std::move(motion));
}

std::vector<index_t> all_segments(const rigid_tool& tool) {
  std::vector<index_t> s(tool.segments());
  std::iota(s.begin(), s.end(), index_t{0});
  return s;
}

segment_hit brute(const rigid_tool& tool, const vec2& y, const vec2& y_prev, index_t held) {
  const auto s = all_segments(tool);
  return choose_segment(tool, s, y, y_prev, held);
}

}  // namespace

TEST_CASE("normals point out of the tool toward the body; corners are classified") {
  const rigid_tool t = punch();
  REQUIRE(t.segments() == 5);
  CHECK(t.normal(0).isApprox(vec2(0, -1)));
  CHECK(t.normal(2).isApprox(vec2(0, -1)));
  CHECK(t.normal(1).isApprox(vec2(-10, -2) / std::sqrt(104.0)));  // slope (10,38)-(12,28), body to the left
  CHECK(t.normal(3).isApprox(vec2(10, -2) / std::sqrt(104.0)));
  CHECK(t.length(1) == doctest::Approx(std::sqrt(104.0)));
  // The recess corners (the tool turns toward the body) are concave for the tool.
  CHECK(t.concave_vertex(1));
  CHECK(t.concave_vertex(4));
  CHECK_FALSE(t.concave_vertex(2));
  CHECK_FALSE(t.concave_vertex(3));
  CHECK_FALSE(t.concave_vertex(0));
  CHECK(t.max_depth() == doctest::Approx(0.5 * 8.5));  // half the shortest segment

  // Body on the left of a left-to-right floor: normal up.
  const rigid_tool floor("floor", {{0, 0}, {35, 0}}, side::left);
  CHECK(floor.normal(0).isApprox(vec2(0, 1)));
}

TEST_CASE("penetration depth, front side and maximum depth") {
  const rigid_tool t = punch();
  double g = -1;
  CHECK(t.catches(2, vec2(18, 28.3), g));
  CHECK(g == doctest::Approx(0.3));
  CHECK_FALSE(t.catches(2, vec2(18, 27.7), g));   // in front of the web
  CHECK_FALSE(t.catches(2, vec2(18, 28.0), g));   // touching is not penetrating
  CHECK_FALSE(t.catches(2, vec2(18, 28 + 5), g)); // deeper than max depth 4.25
  CHECK(t.catches(1, vec2(11, 33.1), g));         // behind the slope: the slope at z=33.1 is r=10.98
  CHECK(g == doctest::Approx((vec2(11, 33.1) - vec2(10, 38)).dot(-t.normal(1))));
  const rigid_tool deep("punch", t.reference_vertices(), side::right, {}, 10.0);
  CHECK(deep.catches(2, vec2(18, 33), g));
  CHECK(g == doctest::Approx(5.0));
  CHECK_THROWS_AS(rigid_tool("bad", {{0, 0}, {0, 0}, {1, 0}}, side::left), rkpm::error);
  CHECK_THROWS_AS(rigid_tool("bad", {{0, 0}}, side::left), rkpm::error);
}

TEST_CASE("concave tool corner: a point in the wedge is caught by both faces; the crossed face wins") {
  const rigid_tool t = punch();
  // Past the end of the recess floor and before the start of the slope, behind both.
  const vec2 y(10.1, 38.1);
  double g0, g1;
  REQUIRE(t.catches(0, y, g0));
  REQUIRE(t.catches(1, y, g1));
  CHECK(g0 == doctest::Approx(0.1));
  CHECK(g1 == doctest::Approx(1.2 / std::sqrt(104.0)));
  // Behind the floor line past its end but inside the slope's band: only the slope.
  CHECK_FALSE(t.catches(0, vec2(10.3, 38.05), g0));
  CHECK(t.catches(1, vec2(10.3, 38.05), g1));
  // No history: the nearest face.
  CHECK(brute(t, y, y, -1).segment == 0);
  // Arriving from the recess, the path crossed the slope within its extent and the floor line
  // only beyond its end: the slope is chosen although it is not the nearest face.
  const segment_hit h = brute(t, y, vec2(9.8, 37.5), -1);
  CHECK(h.segment == 1);
  CHECK(h.gap == doctest::Approx(1.2 / std::sqrt(104.0)));
  // Arriving from above the recess floor's band: the floor.
  CHECK(brute(t, y, vec2(9.9, 37.95), -1).segment == 0);
  // Held at the previous call and nothing crossed now: keep the segment.
  CHECK(brute(t, y, y, 1).segment == 1);
  // Far into the wedge beyond the max depth of both faces: not caught.
  CHECK(brute(t, vec2(16, 44), vec2(16, 44), -1).segment == -1);
}

TEST_CASE("convex tool corner: sliding along the web past its end hands over to the next face") {
  const rigid_tool t = punch();
  // Held by the web, then slides past the corner (24, 28) onto the rim slope.
  const segment_hit h = brute(t, vec2(24.05, 28.6), vec2(23.5, 28.05), 2);
  CHECK(h.segment == 3);
  double g;
  CHECK_FALSE(t.catches(2, vec2(24.05, 28.6), g));
  // Inside the tool near the corner both faces catch; the web, which the path crossed, wins.
  CHECK(brute(t, vec2(23.9, 28.1), vec2(23.8, 27.95), -1).segment == 2);
  // A particle that went around the corner without entering the tool is free.
  CHECK(brute(t, vec2(11.9, 28.01), vec2(12.5, 28.0), 2).segment == -1);
  // Past the open end of the polyline: nothing.
  CHECK(brute(t, vec2(35, 38.1), vec2(34, 37.9), -1).segment == -1);
}

TEST_CASE("the grid search agrees with a brute-force search over all segments") {
  std::mt19937 rng(12345);
  std::vector<rigid_tool> tools = {
      punch(),
      rigid_tool("die", {{0, 0}, {35, 0}, {35, 45}}, side::left),
      rigid_tool("wall", {{-1, 0}, {2, 0}}, side::left, {}, 0.2),
  };
  // A zigzag with many short segments of random direction.
  std::vector<vec2> zig{{0, 0}};
  std::uniform_real_distribution<double> step(0.2, 1.5), turn(-1.2, 1.2);
  double angle = 0;
  for (int i = 0; i < 60; ++i) {
    angle += turn(rng);
    zig.push_back(zig.back() + step(rng) * vec2(std::cos(angle), std::sin(angle)));
  }
  tools.emplace_back("zigzag", zig, side::left);
  for (const rigid_tool& tool : tools) {
    const segment_grid grid(tool);
    vec2 lo = tool.reference_vertices()[0], hi = lo;
    for (const vec2& p : tool.reference_vertices()) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    lo.array() -= 2 * tool.reach();
    hi.array() += 2 * tool.reach();
    std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y()), small(-0.3, 0.3);
    std::uniform_int_distribution<index_t> seg(-1, tool.segments() - 1);
    int caught = 0;
    for (int n = 0; n < 20000; ++n) {
      const vec2 y(ux(rng), uy(rng));
      const vec2 prev = y + tool.max_depth() * vec2(small(rng), small(rng));
      const index_t held = seg(rng);
      // Every segment that catches y is among the grid's candidates.
      const auto cand = grid.candidates(y);
      for (index_t k = 0; k < tool.segments(); ++k) {
        double g;
        if (tool.catches(k, y, g)) {
          bool listed = false;
          for (index_t c : cand) listed = listed || c == k;
          CHECK_MESSAGE(listed, tool.name() << " segment " << k << " misses (" << y.x() << ", " << y.y() << ")");
        }
      }
      const segment_hit a = choose_segment(tool, cand, y, prev, held);
      const segment_hit b = brute(tool, y, prev, held);
      CHECK(a.segment == b.segment);
      CHECK(a.gap == b.gap);
      caught += b.segment >= 0;
    }
    CHECK(caught > 100);  // the random points really exercise contact
    CHECK(grid.cells() > 0);
  }
}

TEST_CASE("tool motion: fixed, constant velocity, prescribed") {
  const rigid_tool fixed = punch();
  CHECK(fixed.vertices(3.0)[2].isApprox(vec2(12, 28)));
  const rigid_tool moving = punch(tool_motion::constant_velocity(vec2(0, -10)));
  CHECK(moving.vertices(0.5)[2].isApprox(vec2(12, 23)));
  CHECK(moving.velocity(0.5).isApprox(vec2(0, -10)));
  const rigid_tool shaken = punch(tool_motion::prescribed([](double t) { return vec2(std::sin(t), 0); },
                                                          [](double t) { return vec2(std::cos(t), 0); }));
  CHECK(shaken.displacement(1.0).x() == doctest::Approx(std::sin(1.0)));
  CHECK(shaken.velocity(1.0).x() == doctest::Approx(std::cos(1.0)));
  CHECK(shaken.vertices(1.0)[0].isApprox(vec2(std::sin(1.0), 38)));
}

TEST_CASE("a rebuilt grid over moving segments finds what a search over all of them finds") {
  // A zigzag chain of short segments (a deformed body's surface), moved and rebuilt several
  // times within the buffers of one reserve(), queried at points near it, as body_contact.hpp
  // does: penetrated_segment over the grid's candidates against all the segments.
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> step(0.2, 1.5), turn(-0.5, 0.5), wobble(-0.05, 0.05);
  const int n = 80;
  std::vector<vec2> base(n);
  double angle = 0;
  base[0] = vec2::Zero();
  for (int i = 1; i < n; ++i) {
    angle += turn(rng);
    base[i] = base[i - 1] + step(rng) * vec2(std::cos(angle), std::sin(angle));
  }
  std::vector<std::array<index_t, 2>> segments;
  for (index_t i = 0; i + 1 < n; ++i) segments.push_back({i, i + 1});
  segment_grid grid;
  grid.reserve(n);
  std::vector<vec2> x(n);
  int caught = 0;
  for (int config = 0; config < 4; ++config) {
    for (int i = 0; i < n; ++i) x[i] = 1.5 * config * vec2(1, -1) + base[i] + vec2(wobble(rng), wobble(rng));
    double shortest = INFINITY;
    vec2 lo = x[0], hi = x[0];
    for (const auto& [a, b] : segments) {
      shortest = std::min(shortest, (x[b] - x[a]).norm());
      lo = lo.cwiseMin(x[a]);
      hi = hi.cwiseMax(x[a]);
    }
    const double depth = 0.5 * shortest;
    grid.rebuild(
        n - 1, [&](index_t s) { return std::pair<vec2, vec2>(x[segments[s][0]], x[segments[s][1]]); }, 2.0 * depth);
    REQUIRE(grid.cells() > 1);
    std::uniform_real_distribution<double> ux(lo.x() - 1, hi.x() + 1), uy(lo.y() - 1, hi.y() + 1);
    const auto all = std::views::iota(index_t{0}, static_cast<index_t>(segments.size()));
    for (int k = 0; k < 20000; ++k) {
      const vec2 P(ux(rng), uy(rng));
      const auto cand = grid.candidates(P);
      CHECK(std::is_sorted(cand.begin(), cand.end()));
      const surface_hit a = penetrated_segment(segments, cand, x, P, depth);
      const surface_hit b = penetrated_segment(segments, all, x, P, depth);
      CHECK(a.segment == b.segment);
      CHECK(a.gap == b.gap);
      caught += b.segment >= 0;
    }
  }
  CHECK(caught > 100);  // the random points really exercise contact
}
