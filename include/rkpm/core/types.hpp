#pragma once
// Small fixed-size types shared by every part of rkpm. Coordinates are (x, y) in plane
// strain and (r, z) in axisymmetric geometry; all quantities are SI inside the library.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>

namespace rkpm {

using index_t = std::ptrdiff_t;
// An index stored once per table entry, quadrature point or cell (particle, node and cell
// numbers, table offsets): 32 bits, since those arrays are most of a run's memory. Builders
// refuse sizes past its range with an error.
using stored_index = std::int32_t;

template <int Dim>
using vec = Eigen::Matrix<double, Dim, 1>;

using vec2 = Eigen::Vector2d;
using mat2 = Eigen::Matrix2d;
using mat3 = Eigen::Matrix3d;

// A vec2 kept as two doubles, for a per-point state: trivially copyable (a state is checkpointed
// as its bytes) and 8-byte aligned (no padding after the state's doubles); read back as a vec2.
struct packed_vec2 {
  double x = 0.0, y = 0.0;

  packed_vec2() = default;
  packed_vec2(const vec2& v) : x(v[0]), y(v[1]) {}
  operator vec2() const { return {x, y}; }
};

}  // namespace rkpm
