// particle_set and make_grid_particles: grid positions, per-direction supports a = s h, and
// tributary volumes (corner h_x h_y / 4, edge / 2, interior h_x h_y) that add up to the box;
// validate() accepts the result and bad arguments are errors.

#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include <rkpm/discretization/particle_set.hpp>

using rkpm::index_t;
using rkpm::vec;
using rkpm::vec2;

TEST_CASE("2D grid: positions, supports, volumes") {
  // The Taylor bar set: 21 x 51 particles on [0, 3.2e-3] x [0, 32.4e-3] m.
  const vec2 hi(3.2e-3, 32.4e-3);
  const auto p = rkpm::make_grid_particles<2>(vec2(0, 0), hi, {21, 51}, 1.75);
  REQUIRE(p.size() == 21 * 51);
  CHECK_NOTHROW(p.validate());
  const vec2 h(0.16e-3, 0.648e-3);
  double total = 0.0;
  for (index_t n = 0; n < p.size(); ++n) {
    const index_t i = n % 21, j = n / 21;  // x fastest
    CHECK(p.position[n][0] == doctest::Approx(i * h[0]).epsilon(1e-14));
    CHECK(p.position[n][1] == doctest::Approx(j * h[1]).epsilon(1e-14));
    CHECK(p.support[n][0] == doctest::Approx(1.75 * h[0]).epsilon(1e-14));
    CHECK(p.support[n][1] == doctest::Approx(1.75 * h[1]).epsilon(1e-14));
    const double wx = (i == 0 || i == 20) ? 0.5 : 1.0, wy = (j == 0 || j == 50) ? 0.5 : 1.0;
    CHECK(p.volume[n] == doctest::Approx(wx * wy * h[0] * h[1]).epsilon(1e-13));
    total += p.volume[n];
  }
  CHECK(total == doctest::Approx(hi[0] * hi[1]).epsilon(1e-13));
}

TEST_CASE("1D grid: volumes add to the length") {
  const auto p = rkpm::make_grid_particles<1>(vec<1>(-1.0), vec<1>(2.0),
                                              Eigen::Matrix<int, 1, 1>(7), 2.0);
  REQUIRE(p.size() == 7);
  double total = 0.0;
  for (double v : p.volume) total += v;
  CHECK(total == doctest::Approx(3.0).epsilon(1e-15));
  CHECK(p.volume.front() == doctest::Approx(0.25).epsilon(1e-15));
  CHECK(p.position.back()[0] == doctest::Approx(2.0).epsilon(1e-15));
  CHECK(p.support[3][0] == doctest::Approx(1.0).epsilon(1e-15));
}

TEST_CASE("grid arguments are checked") {
  auto message = [](auto f) -> std::string {
    try {
      f();
    } catch (const rkpm::error& e) {
      return e.what();
    }
    return "";
  };
  CHECK(message([] { rkpm::make_grid_particles<2>(vec2(0, 0), vec2(1, 1), {1, 5}, 2.0); })
            .find("at least 2") != std::string::npos);
  CHECK(message([] { rkpm::make_grid_particles<2>(vec2(0, 0), vec2(0, 1), {3, 5}, 2.0); })
            .find("empty box") != std::string::npos);
  CHECK(message([] { rkpm::make_grid_particles<2>(vec2(0, 0), vec2(1, 1), {3, 5}, 0.0); })
            .find("support factor") != std::string::npos);
  rkpm::particle_set<2> p = rkpm::make_grid_particles<2>(vec2(0, 0), vec2(1, 1), {3, 3}, 2.0);
  p.position[4] = vec2(std::nan(""), 0.0);
  CHECK(message([&] { p.validate(); }).find("particle 4") != std::string::npos);
}
