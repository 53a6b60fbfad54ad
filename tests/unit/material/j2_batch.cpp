// The batched J2 update (material/j2_batch.hpp) against the point-by-point update it stands for
// (j2_plasticity::kirchhoff_stress, checked against theory in j2_paths.cpp, j2_shear.cpp and
// j2_uniaxial.cpp), that is the formulas of basic_j2_trial and hencky.hpp at a vector type
// against the same formulas at double, with the yield checks and returns of the lanes: on lanes that stay elastic, yield, turn rigidly or mix all three, with the
// linear law's closed-form return and the power law's Newton iteration, every stress entry and
// every state member must have the scalar update's bits. A failed return must leave every state
// as it was. At every width users build: the native vector of this build (core/simd.hpp) and
// 2, 4 and 8 lanes (simd_of<N>, fixed-size vectors that need no AVX2 or AVX-512 to run).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>
#include <vector>

#include <rkpm/material/hardening/linear.hpp>
#include <rkpm/material/hardening/power_law.hpp>
#include <rkpm/material/j2_batch.hpp>

#include "support/paper_materials.hpp"

namespace j2_batch_test {

using rkpm::block_matrix;
using rkpm::mat3;
using rkpm::material_step;
using rkpm::material::j2_plasticity;
using rkpm::material::j2_state;
namespace h = rkpm::material::hardening;

using rkpm::test::paper_materials::copper;
using rkpm::test::paper_materials::copper_hardening;
using rkpm::test::paper_materials::wheel_hardening;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const block_matrix& a, const block_matrix& b) {
  return same_bits(a.xx, b.xx) && same_bits(a.xy, b.xy) && same_bits(a.yx, b.yx) && same_bits(a.yy, b.yy) &&
         same_bits(a.zz, b.zz);
}

// Lane k's deformation at stage n of a path: kind 0 stays elastic (strains of 1e-4), kind 1
// yields and keeps flowing (compression, shear, hoop stretch to about 0.3), kind 2 only turns
// (b_trial = I, a repeated eigenvalue), kind 3 unloads after yielding.
mat3 deformation(int kind, int k, int n) {
  const double t = 0.02 * n * (1.0 + 0.1 * k);
  mat3 F = mat3::Identity();
  switch (kind) {
    case 0: F(0, 0) += 1e-4 * t; F(0, 1) += 2e-5 * k * t; break;
    case 1: F(0, 0) -= 0.3 * t; F(0, 1) += 0.2 * std::sin(t); F(1, 0) -= 0.1 * t * t; F(2, 2) += 0.2 * t; break;
    case 2: F << std::cos(t), -std::sin(t), 0, std::sin(t), std::cos(t), 0, 0, 0, 1; break;
    default: {
      const double s = n < 10 ? t : 0.4 - t;
      F(0, 0) -= 0.2 * s; F(1, 1) += 0.05 * s; F(2, 2) += 0.1 * s;
    }
  }
  return F;
}

// Runs lanes of the given kinds through 20 stages, batched and point by point, and checks
// every stress and state bit.
template <class V, class H>
void check_lanes(const j2_plasticity<H>& m, const std::array<int, rkpm::lanes_of<V>>& kinds) {
  constexpr int lanes = rkpm::lanes_of<V>;
  std::vector<j2_state> batch(lanes, m.initial_state()), scalar = batch;
  int yielded = 0;
  for (int n = 1; n <= 20; ++n) {
    std::array<mat3, lanes> F;
    for (int k = 0; k < lanes; ++k) F[k] = deformation(kinds[k], k, n);
    const material_step step{1e-7, 1e-7 * n, std::numeric_limits<double>::quiet_NaN()};
    const rkpm::basic_block_lanes<V> tau = rkpm::material::kirchhoff_stress_batch(
        m, rkpm::gather_block<V>([&](int k) { return block_matrix::of(F[k]); }), batch.data(), step);
    for (int k = 0; k < lanes; ++k) {
      CAPTURE(kinds[k]);
      CAPTURE(k);
      CAPTURE(n);
      const double before = scalar[k].equivalent_plastic_strain;
      const block_matrix expected = block_matrix::of(m.kirchhoff_stress(F[k], scalar[k], step));
      yielded += scalar[k].equivalent_plastic_strain > before;
      CHECK(same_bits(rkpm::lane_of(tau, k), expected));
      CHECK(same_bits(batch[k].elastic_left_cauchy_green, scalar[k].elastic_left_cauchy_green));
      CHECK(same_bits(batch[k].previous_deformation, scalar[k].previous_deformation));
      CHECK(same_bits(batch[k].equivalent_plastic_strain, scalar[k].equivalent_plastic_strain));
      CHECK(same_bits(batch[k].plastic_work, scalar[k].plastic_work));
    }
  }
  const bool any_yielding = std::find_if(kinds.begin(), kinds.end(), [](int k) { return k == 1 || k == 3; }) != kinds.end();
  CHECK((yielded > 0) == any_yielding);  // the paths reach the branches they are meant to
}

template <class V, class H>
void check_all_mixes(const j2_plasticity<H>& m) {
  constexpr int lanes = rkpm::lanes_of<V>;
  for (int kind = 0; kind < 4; ++kind) {
    std::array<int, lanes> same;
    same.fill(kind);
    check_lanes<V>(m, same);
  }
  // Every kind beside every other: lanes k and k + 1 differ, and 4 or more lanes hold all four.
  std::array<int, lanes> mixed;
  for (int k = 0; k < lanes; ++k) mixed[k] = (k * 3 + 1) % 4;
  check_lanes<V>(m, mixed);
}

// The widths: this build's native vector, and 2, 4 and 8 lanes on any x86-64 (doctest's
// template test cases, TEST_CASE_TEMPLATE_DEFINE and _APPLY over this list).
using widths = std::tuple<rkpm::simd_double, rkpm::simd_of<2>, rkpm::simd_of<4>, rkpm::simd_of<8>>;

TEST_CASE_TEMPLATE_DEFINE("j2_batch: linear hardening, every lane as the scalar update", V, j2_batch_linear) {
  CAPTURE(rkpm::lanes_of<V>);
  check_all_mixes<V>(j2_plasticity<h::linear>(copper, copper_hardening));
}

TEST_CASE_TEMPLATE_DEFINE("j2_batch: power-law hardening (Newton return), every lane as the scalar update", V, j2_batch_power_law) {
  CAPTURE(rkpm::lanes_of<V>);
  check_all_mixes<V>(j2_plasticity<h::power_law>(copper, wheel_hardening));
}

TEST_CASE_TEMPLATE_DEFINE("j2_batch: a return that fails leaves every state as it was", V, j2_batch_failed_return) {
  constexpr int lanes = rkpm::lanes_of<V>;
  // One Newton update is too few for the power law's return from a large overstress.
  const j2_plasticity<h::power_law> m(copper, wheel_hardening, 1e-12, 1);
  std::vector<j2_state> states(lanes, m.initial_state());
  const std::vector<j2_state> before = states;
  const mat3 F = deformation(1, 0, 10);
  CHECK_THROWS_WITH(rkpm::material::kirchhoff_stress_batch(
                        m, rkpm::gather_block<V>([&](int) { return block_matrix::of(F); }),
                        states.data(), material_step{}),
                    doctest::Contains("did not converge"));
  for (int k = 0; k < lanes; ++k) {
    CHECK(same_bits(states[k].elastic_left_cauchy_green, before[k].elastic_left_cauchy_green));
    CHECK(same_bits(states[k].previous_deformation, before[k].previous_deformation));
    CHECK(states[k].equivalent_plastic_strain == before[k].equivalent_plastic_strain);
  }
}

TEST_CASE_TEMPLATE_APPLY(j2_batch_linear, widths);
TEST_CASE_TEMPLATE_APPLY(j2_batch_power_law, widths);
TEST_CASE_TEMPLATE_APPLY(j2_batch_failed_return, widths);

}  // namespace j2_batch_test
