#pragma once
// simd_double: the vector of doubles the batched material update computes with (one point per
// lane), std::experimental::simd's native width for the flags the user compiles with: 2 lanes
// with x86-64's baseline SSE2, 4 with AVX2 (-march=x86-64-v3), 8 with AVX-512. Its +, -, *, /
// and sqrt round as the scalar operations do, so a formula written once for a number type T,
// double for one point or a vector V for its lanes (material/hencky.hpp, material/j2_plasticity.hpp,
// solver/point_force_terms.hpp), gives each lane the bits it gives that lane's point. The
// transcendental functions are taken lane by lane from the C library (lanewise), for the same
// reason: a vectorized log or exp would move results by rounding. block_lanes holds a block
// matrix of every lane (core/block_matrix.hpp), one entry per vector.
// The batched code is written for any such vector type V (simd_of<N>: N lanes whatever the
// flags, which the compiler splits over the registers it has), so that the tests run the widths
// of every instruction set on any x86-64 (tests/unit/solver/lane_widths.cpp).

#include <cmath>
#include <concepts>
#include <experimental/simd>

#include <rkpm/core/block_matrix.hpp>
#include <rkpm/core/hot_inline.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

namespace stdx = std::experimental;

using simd_double = stdx::native_simd<double>;
using simd_mask = simd_double::mask_type;
inline constexpr int simd_lanes = static_cast<int>(simd_double::size());
// N lanes whatever the instruction set.
template <int N>
using simd_of = stdx::fixed_size_simd<double, N>;
// The lanes of a vector type V.
template <class V>
inline constexpr int lanes_of = static_cast<int>(V::size());

// What the formulas written once for a number type T (double or a vector V) need beyond +, -, *,
// / and comparisons: the truth of a comparison (bool, or V's mask), sqrt, a masked assignment and
// a scalar function of each lane.
template <class T>
using mask_of = decltype(T(0.0) > 0.0);

RKPM_HOT_INLINE double sqrt_of(double x) { return std::sqrt(x); }
template <class V>
  requires(!std::same_as<V, double>)
RKPM_HOT_INLINE V sqrt_of(const V& x) {
  return stdx::sqrt(x);
}

// x = value where mask holds (for one point, an if).
RKPM_HOT_INLINE void assign_where(bool mask, double& x, double value) {
  if (mask) x = value;
}
template <class V>
  requires(!std::same_as<V, double>)
RKPM_HOT_INLINE void assign_where(const typename V::mask_type& mask, V& x, const V& value) {
  stdx::where(mask, x) = value;
}
template <class T>
RKPM_HOT_INLINE void assign_where(const mask_of<T>& mask, basic_block_matrix<T>& x, const basic_block_matrix<T>& value) {
  assign_where(mask, x.xx, value.xx);
  assign_where(mask, x.xy, value.xy);
  assign_where(mask, x.yx, value.yx);
  assign_where(mask, x.yy, value.yy);
  assign_where(mask, x.zz, value.zz);
}

// The lanes of x, each passed through f (a scalar function of a double); f(x) for one point.
template <class F>
RKPM_HOT_INLINE double lanewise(double x, F&& f) {
  return f(x);
}
template <class V, class F>
  requires(!std::same_as<V, double>)
RKPM_HOT_INLINE V lanewise(const V& x, F&& f) {
  return V([&](auto lane) { return f(x[lane]); });
}

// Lane k of the result is get(k): a gather from an array of structures.
template <class V = simd_double, class Get>
V gather_lanes(Get&& get) {
  return V([&](auto lane) { return get(static_cast<int>(lane)); });
}

template <class V = simd_double>
using basic_block_lanes = basic_block_matrix<V>;
using block_lanes = basic_block_lanes<simd_double>;

// The block matrices item(0), item(1), ... as lanes.
template <class V = simd_double, class Item>
basic_block_lanes<V> gather_block(Item&& item) {
  return {gather_lanes<V>([&](int k) { return item(k).xx; }), gather_lanes<V>([&](int k) { return item(k).xy; }),
          gather_lanes<V>([&](int k) { return item(k).yx; }), gather_lanes<V>([&](int k) { return item(k).yy; }),
          gather_lanes<V>([&](int k) { return item(k).zz; })};
}

// Lane k's block matrix.
template <class V>
block_matrix lane_of(const basic_block_lanes<V>& a, int k) {
  return {a.xx[k], a.xy[k], a.yx[k], a.yy[k], a.zz[k]};
}

}  // namespace rkpm
