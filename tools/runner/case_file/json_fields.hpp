#pragma once
// Reading the fields of a case file with every mistake reported through diagnostics (one line
// each, with the JSON pointer and the fix) instead of an exception at the first: an
// object_reader knows the keys an object may have (anything else is reported with the
// closest known key) and reads typed fields (a missing required field or a wrong type is
// reported and read as nullopt). Examples given to the readers ("8930") appear in the fixes.

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/types.hpp>

#include "../json.hpp"
#include "diagnostics.hpp"

namespace rkpm::runner::case_file {

// What a JSON value is, for messages: "a string \"abc\"", "an array", "null".
inline std::string describe(const json& v) {
  if (v.is_object()) return "an object";
  if (v.is_array()) return "an array";
  if (v.is_string()) return fmt::format("a string {}", v.dump());
  if (v.is_boolean()) return fmt::format("{}", v.dump());
  if (v.is_null()) return "null";
  return fmt::format("the number {}", v.dump());
}

// ---- single values ----------------------------------------------------------------------
inline std::optional<double> to_number(diagnostics& d, const json& v, const std::string& at, std::string_view example) {
  if (v.is_number()) {
    const double x = v.get<double>();
    if (std::isfinite(x)) return x;
    d.error(at, fmt::format("{} is not finite; give a finite number, e.g. {}", v.dump(), example));
    return std::nullopt;
  }
  d.error(at, fmt::format("expected a number, got {}; give e.g. {}", describe(v), example));
  return std::nullopt;
}

inline std::optional<int> to_integer(diagnostics& d, const json& v, const std::string& at, std::string_view example) {
  if (v.is_number()) {
    const double x = v.get<double>();
    if (x == std::round(x) && std::abs(x) < 1e9) return static_cast<int>(x);
  }
  d.error(at, fmt::format("expected a whole number (a count), got {}; give e.g. {}", describe(v), example));
  return std::nullopt;
}

inline std::optional<std::string> to_text(diagnostics& d, const json& v, const std::string& at, std::string_view example) {
  if (v.is_string()) return v.get<std::string>();
  d.error(at, fmt::format("expected a string, got {}; give e.g. \"{}\"", describe(v), example));
  return std::nullopt;
}

inline std::optional<vec2> to_vec2(diagnostics& d, const json& v, const std::string& at, std::string_view example) {
  if (v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number()) {
    const vec2 p(v[0].get<double>(), v[1].get<double>());
    if (p.allFinite()) return p;
  }
  d.error(at, fmt::format("expected a pair of finite numbers [x, y], got {}; give e.g. {}",
                          v.is_array() ? v.dump() : describe(v), example));
  return std::nullopt;
}

// A list of at least `min_count` points [[x, y], ...].
inline std::optional<std::vector<vec2>> to_points(diagnostics& d, const json& v, const std::string& at,
                                                  std::size_t min_count, std::string_view example) {
  if (!v.is_array() || v.size() < min_count) {
    d.error(at, fmt::format("expected a list of at least {} points [[x, y], ...], got {}; give e.g. {}", min_count,
                            v.is_array() ? fmt::format("{} points", v.size()) : describe(v), example));
    return std::nullopt;
  }
  std::vector<vec2> out;
  bool ok = true;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto p = to_vec2(d, v[i], child_pointer(at, i), "[0.01, 0.02]");
    if (p) out.push_back(*p);
    ok = ok && p.has_value();
  }
  if (!ok) return std::nullopt;
  return out;
}

// ---- objects ----------------------------------------------------------------------------
class object_reader {
 public:
  // Reports a value that is not an object, and every key not among `known`.
  object_reader(diagnostics& d, const json& value, std::string pointer, std::vector<std::string_view> known)
      : d_(d), pointer_(std::move(pointer)), known_(std::move(known)) {
    if (!value.is_object()) {
      d_.error(pointer_, fmt::format("expected an object {{...}}, got {}; give an object with the fields {}",
                                     describe(value), list_choices(known_)));
      return;
    }
    value_ = &value;
    for (const auto& [key, _] : value.items())
      if (std::find(known_.begin(), known_.end(), key) == known_.end()) {
        d_.error(at(key), fmt::format("unknown field '{}'; {}", key, suggest(key, known_, "the fields here are")));
        if (auto meant = closest_choice(key, known_)) misspelt_.push_back(std::move(*meant));
      }
  }

  bool valid() const { return value_ != nullptr; }
  diagnostics& diag() const { return d_; }
  const std::string& pointer() const { return pointer_; }
  std::string at(std::string_view key) const { return child_pointer(pointer_, key); }
  const json* find(std::string_view key) const {
    if (!value_) return nullptr;
    const auto it = value_->find(key);
    return it == value_->end() ? nullptr : &*it;
  }
  // The value of a required field, or nullptr after reporting it missing.
  const json* required(std::string_view key, std::string_view example) const {
    if (!value_) return nullptr;
    const json* v = find(key);
    // A misspelt key was reported already, with this key as its correction.
    const bool misspelt = std::find(misspelt_.begin(), misspelt_.end(), key) != misspelt_.end();
    if (!v && !misspelt) d_.error(pointer_, fmt::format("missing field '{}'; add \"{}\": {}", key, key, example));
    return v;
  }

  std::optional<double> number(std::string_view key, std::string_view example) const {
    const json* v = required(key, example);
    return v ? to_number(d_, *v, at(key), example) : std::nullopt;
  }
  double number_or(std::string_view key, double fallback) const {
    const json* v = find(key);
    return v ? to_number(d_, *v, at(key), fmt::format("{:g}", fallback)).value_or(fallback) : fallback;
  }
  std::optional<int> integer(std::string_view key, std::string_view example) const {
    const json* v = required(key, example);
    return v ? to_integer(d_, *v, at(key), example) : std::nullopt;
  }
  int integer_or(std::string_view key, int fallback) const {
    const json* v = find(key);
    return v ? to_integer(d_, *v, at(key), fmt::format("{}", fallback)).value_or(fallback) : fallback;
  }
  std::optional<std::string> text(std::string_view key, std::string_view example) const {
    const json* v = required(key, fmt::format("\"{}\"", example));
    return v ? to_text(d_, *v, at(key), example) : std::nullopt;
  }
  std::string text_or(std::string_view key, std::string_view fallback) const {
    const json* v = find(key);
    return v ? to_text(d_, *v, at(key), fallback).value_or(std::string(fallback)) : std::string(fallback);
  }
  bool boolean_or(std::string_view key, bool fallback) const {
    const json* v = find(key);
    if (!v) return fallback;
    if (v->is_boolean()) return v->get<bool>();
    d_.error(at(key), fmt::format("expected true or false, got {}; give e.g. {}", describe(*v), fallback));
    return fallback;
  }
  std::optional<vec2> point(std::string_view key, std::string_view example) const {
    const json* v = required(key, example);
    return v ? to_vec2(d_, *v, at(key), example) : std::nullopt;
  }
  vec2 point_or(std::string_view key, const vec2& fallback) const {
    const json* v = find(key);
    return v ? to_vec2(d_, *v, at(key), fmt::format("[{:g}, {:g}]", fallback.x(), fallback.y())).value_or(fallback)
             : fallback;
  }

  // A name among `choices` (policy names, edge names, ...): required when `fallback` is empty.
  template <class Choices>
  std::optional<std::string> choice(std::string_view key, const Choices& choices, std::string_view what,
                                    std::string_view fallback = {}) const {
    std::optional<std::string> name;
    if (fallback.empty()) {
      name = text(key, *std::begin(choices));
    } else {
      if (!find(key)) return std::string(fallback);
      name = to_text(d_, *find(key), at(key), fallback);
    }
    if (!name) return std::nullopt;
    for (const auto& c : choices)
      if (*name == std::string_view(c)) return name;
    d_.error(at(key), fmt::format("unknown {} '{}'; {}", what, *name, suggest(*name, choices)));
    return std::nullopt;
  }

 private:
  diagnostics& d_;
  const json* value_ = nullptr;
  std::string pointer_;
  std::vector<std::string_view> known_;
  std::vector<std::string> misspelt_;  // known keys suggested for unknown ones
};

// ---- ranges -----------------------------------------------------------------------------
// Each reports "NAME = value must ...; give ..." and returns whether the value passed.
inline bool check_positive(diagnostics& d, const std::string& at, double value, std::string_view example) {
  if (value > 0.0) return true;
  d.error(at, fmt::format("{:g} must be positive; give e.g. {}", value, example));
  return false;
}
inline bool check_non_negative(diagnostics& d, const std::string& at, double value, std::string_view example) {
  if (value >= 0.0) return true;
  d.error(at, fmt::format("{:g} must not be negative; give e.g. {}", value, example));
  return false;
}

}  // namespace rkpm::runner::case_file
