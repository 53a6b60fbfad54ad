#pragma once
// Named, typed, unit-carrying parameters of a case, so that the runner can list them
// (`tools/rkpm run CASE --help`) and override any of them (`--set NAME=VALUE`) without
// recompiling. Each case's parameter struct lists its fields once:
//   static constexpr std::array fields = {parameter<P>{"velocity_m_s", "m/s", "...", &P::velocity_m_s}, ...};
// A field is a double (a physical quantity, SI units), an int (a count: whole numbers only,
// from a smallest value given in the declaration) or a bool (a switch: 0 or 1).

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <variant>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>

namespace rkpm::cases {

template <class P>
struct parameter {
  std::string_view name;
  std::string_view unit;
  std::string_view description;
  std::variant<double P::*, int P::*, bool P::*> member;
  int minimum = std::numeric_limits<int>::min();  // smallest accepted value of an int field
};

// Calls fn(value) with the field's value in p, as its own type (double, int or bool).
template <class P, class Fn>
void visit_value(const parameter<P>& f, const P& p, Fn&& fn) {
  std::visit([&](auto member) { fn(p.*member); }, f.member);
}

// Sets the parameter called `name` from its text value. Unknown names, unreadable or
// non-finite numbers, fractions for a count and anything but 0 or 1 for a switch are errors
// that say what is accepted.
template <class P>
void set_parameter(P& p, std::string_view name, std::string_view text) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  for (const auto& f : P::fields) {
    if (f.name != name) continue;
    if (const auto m = std::get_if<double P::*>(&f.member)) {
      double value = 0.0;
      const auto [end, ec] = std::from_chars(first, last, value);
      if (ec != std::errc() || end != last || !std::isfinite(value))
        fail("{} takes a finite number in {}, got '{}'", name, f.unit, text);
      p.*(*m) = value;
    } else if (const auto m = std::get_if<int P::*>(&f.member)) {
      int value = 0;
      const auto [end, ec] = std::from_chars(first, last, value);
      if (ec != std::errc() || end != last) {
        double x = 0.0;
        const auto [xend, xec] = std::from_chars(first, last, x);
        if (xec == std::errc() && xend == last && std::isfinite(x) && std::abs(x) < 1e9)
          fail("{} is a count and takes a whole number, got '{}' (e.g. {}={})", name, text, name,
               std::max(f.minimum, static_cast<int>(std::lround(x))));
        fail("{} is a count and takes a whole number, got '{}'", name, text);
      }
      if (value < f.minimum) fail("{} must be at least {}, got {}", name, f.minimum, value);
      p.*(*m) = value;
    } else {
      const auto b = std::get<bool P::*>(f.member);
      if (text == "1" || text == "true")
        p.*b = true;
      else if (text == "0" || text == "false")
        p.*b = false;
      else
        fail("{} is a switch and takes 1 (on) or 0 (off), got '{}'", name, text);
    }
    return;
  }
  std::string names;
  for (const auto& f : P::fields) names += fmt::format("{}{}", names.empty() ? "" : ", ", f.name);
  fail("unknown parameter '{}'; the parameters are: {}", name, names);
}

// The fields of several lists as one (a case that shares a block of parameters with another).
template <class P, std::size_t... N>
constexpr std::array<parameter<P>, (N + ...)> join_fields(const std::array<parameter<P>, N>&... lists) {
  std::array<parameter<P>, (N + ...)> out{};
  std::size_t k = 0;
  ((std::copy(lists.begin(), lists.end(), out.begin() + k), k += N), ...);
  return out;
}

// One line per parameter: name, default (the value in p), unit and description.
template <class P>
std::string describe_parameters(const P& p) {
  std::string out;
  for (const auto& f : P::fields) {
    std::string value;
    visit_value(f, p, [&](auto v) { value = fmt::format("{:g}", static_cast<double>(v)); });
    out += fmt::format("  {:<26} {:>12} {:<8} {}\n", f.name, value, f.unit, f.description);
  }
  return out;
}

// Throws unless value > 0 (and finite): "name = value must be positive".
inline void require_positive(std::string_view name, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) fail("{} = {} must be positive", name, value);
}

// Particle count along one direction at resolution factor k: the paper's n particles have
// n - 1 gaps; k multiplies the gaps.
inline int refined_count(int paper_count, int resolution) { return (paper_count - 1) * resolution + 1; }

}  // namespace rkpm::cases
