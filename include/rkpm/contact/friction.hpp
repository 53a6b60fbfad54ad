#pragma once
// Friction policies for particle-to-segment contact (docs/method.md (57)-(58), section 6.6).
// limit(trial, f_n) turns the tangential force that would make the particle stick, the
// sticking force (P6) f_st = -m v_T / dt, into the force the law allows:
//   frictionless: zero;
//   coulomb (P5): f_t = -min(mu |f_n|, |f_st|) v_T / |v_T|, i.e. f_st capped at mu |f_n|.

#include <cmath>
#include <string_view>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm::contact::friction {

struct frictionless {
  static constexpr std::string_view name = "frictionless";
  void validate() const {}
  vec2 limit(const vec2& /*trial*/, double /*normal*/) const { return vec2::Zero(); }
};

struct coulomb {
  static constexpr std::string_view name = "coulomb";
  double coefficient = 0.0;  // mu_k, dimensionless

  void validate() const {
    if (!(coefficient >= 0.0) || !std::isfinite(coefficient))
      fail("coulomb friction: coefficient {} must be finite and >= 0 (0 means frictionless)", coefficient);
  }
  vec2 limit(const vec2& trial, double normal) const {
    const double cap = coefficient * std::abs(normal);
    const double size = trial.norm();
    return size <= cap ? trial : vec2(trial * (cap / size));
  }
};

}  // namespace rkpm::contact::friction
