// Geometry policies: plane strain has unit weight and F33 = 1; axisymmetric has weight 2 pi R
// and hoop stretch 1 + u_r / R (a ring of radius R moved to R + u_r is stretched by (R + u_r) / R).

#include <doctest/doctest.h>

#include <numbers>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>

namespace test_unit_geometry_geometry {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

static_assert(Geometry<geometry::plane_strain> && Geometry<geometry::axisymmetric>);
static_assert(!geometry::plane_strain::is_axisymmetric && geometry::axisymmetric::is_axisymmetric);

TEST_CASE("plane strain") {
  CHECK(geometry::plane_strain::weight_factor(vec2(3, -2)) == 1.0);
  CHECK(geometry::plane_strain::out_of_plane_stretch(vec2(0.5, 0.2), vec2(3, -2)) == 1.0);
  CHECK(geometry::plane_strain::name == "plane_strain");
}

TEST_CASE("axisymmetric") {
  const vec2 X(0.25, 7.0);
  CHECK(geometry::axisymmetric::weight_factor(X) == doctest::Approx(0.5 * std::numbers::pi).epsilon(1e-15));
  // Circumference ratio of the ring: (R + u_r) / R, independent of u_z.
  CHECK(geometry::axisymmetric::out_of_plane_stretch(vec2(0.05, 3.0), X) == doctest::Approx(0.3 / 0.25).epsilon(1e-15));
  CHECK(geometry::axisymmetric::out_of_plane_stretch(vec2(-0.05, 0.0), X) == doctest::Approx(0.2 / 0.25).epsilon(1e-15));
  CHECK(geometry::axisymmetric::name == "axisymmetric");
}

}  // namespace test_unit_geometry_geometry
