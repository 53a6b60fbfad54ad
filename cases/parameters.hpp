#pragma once
// Named, typed, unit-carrying parameters of a case, so that the runner can list them
// (`tools/rkpm run CASE --help`) and override any of them (`--set NAME=VALUE`) without
// recompiling. Each case's parameter struct lists its fields once:
//   static constexpr std::array fields = {parameter<P>{"velocity_m_s", "m/s", "...", &P::velocity_m_s}, ...};

#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>

namespace rkpm::cases {

template <class P>
struct parameter {
  std::string_view name;
  std::string_view unit;
  std::string_view description;
  double P::*member;
};

// Sets the parameter called `name` from its text value; unknown names and unreadable or
// non-finite values are errors that say what is accepted.
template <class P>
void set_parameter(P& p, std::string_view name, std::string_view text) {
  for (const auto& f : P::fields) {
    if (f.name != name) continue;
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
      fail("--set {}={}: '{}' is not a number (give the value in {})", name, text, text, f.unit);
    p.*(f.member) = value;
    return;
  }
  std::string names;
  for (const auto& f : P::fields) names += fmt::format("{}{}", names.empty() ? "" : ", ", f.name);
  fail("unknown parameter '{}'; the parameters are: {}", name, names);
}

// One line per parameter: name, default (the value in p), unit and description.
template <class P>
std::string describe_parameters(const P& p) {
  std::string out;
  for (const auto& f : P::fields)
    out += fmt::format("  {:<26} {:>12g} {:<8} {}\n", f.name, p.*(f.member), f.unit, f.description);
  return out;
}

// Throws unless value > 0 (and finite): "name = value must be positive".
inline void require_positive(std::string_view name, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) fail("{} = {} must be positive", name, value);
}

// Particle count along one direction at resolution factor k: the paper's n particles have
// n - 1 gaps; k multiplies the gaps.
inline int refined_count(double paper_count, int resolution) {
  return static_cast<int>(std::lround((paper_count - 1.0) * resolution)) + 1;
}

}  // namespace rkpm::cases
