#pragma once
// Reading what expressions need (expressions.hpp): the top-level "constants" and a vector a body
// or tool gives as numbers or expressions. Each expression is parsed here, so that a syntax
// error or an unknown name is reported with the others before anything is built; one that
// names no variable is evaluated here and kept as the number it gives. (Whether an expression
// of x, y stays finite over a body is checked where the body's particles exist: body_fields.hpp.)

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "case_description.hpp"
#include "expressions.hpp"
#include "json_fields.hpp"

namespace rkpm::runner::case_file {

// "constants": {"w": 100, "v0": -190}: numbers, under names that are not variables.
inline constant_table read_constants(diagnostics& d, const json* value, const std::string& at) {
  constant_table constants;
  if (!value) return constants;
  if (!value->is_object()) {
    d.error(at, fmt::format("expected an object of named numbers, got {}; give e.g. {{\"w\": 100}}", describe(*value)));
    return constants;
  }
  for (const auto& [name, v] : value->items()) {
    const std::string vat = child_pointer(at, name);
    if (const std::string problem = constant_name_problem(name); !problem.empty()) {
      d.error(vat, problem);
      continue;
    }
    if (const auto x = to_number(d, v, vat, "100 (a constant is a number; expressions use it by name)"))
      constants.emplace(name, *x);
  }
  return constants;
}

namespace detail {

// "x, y" / "t" / "no variable", for messages.
inline std::string variables_phrase(const std::vector<std::string>& variables) {
  return variables.empty() ? "no variable" : list_choices(variables);
}

}  // namespace detail

// A vector [a, b] at `at`: each a number, or an expression (a string) of `variables` and the
// constants. `example` is a fix to show ("[0, -190]").
inline std::optional<vector_field> to_vector_field(diagnostics& d, const json& v, const std::string& at,
                                                   const std::vector<std::string>& variables,
                                                   const constant_table& constants, std::string_view example) {
  if (!v.is_array() || v.size() != 2) {
    d.error(at, fmt::format("expected [x, y]: two numbers, or expressions (strings) of {}, got {}; give e.g. {}",
                            detail::variables_phrase(variables),
                            v.is_array() ? fmt::format("{} components", v.size()) : describe(v), example));
    return std::nullopt;
  }
  vector_field f;
  f.at = at;
  bool ok = true;
  for (int k = 0; k < 2; ++k) {
    const json& c = v[static_cast<std::size_t>(k)];
    const std::string cat = child_pointer(at, static_cast<std::size_t>(k));
    if (c.is_number()) {
      const auto x = to_number(d, c, cat, "0");
      ok = ok && x.has_value();
      f.value[k] = x.value_or(0.0);
      continue;
    }
    if (!c.is_string()) {
      d.error(cat, fmt::format("expected a number or an expression (a string) of {}, got {}; give e.g. {}",
                               detail::variables_phrase(variables), describe(c), example));
      ok = false;
      continue;
    }
    std::string why;
    const auto e = expression::parse(c.get<std::string>(), variables, constants, why);
    if (!e) {
      d.error(cat, why);
      ok = false;
    } else if (e->uses_variables()) {
      f.expression[k] = e->text();
    } else {  // a number written as an expression
      const double x = (*e)({});
      if (!std::isfinite(x)) {
        d.error(cat, fmt::format("the expression \"{}\" gives {}; give a finite value", e->text(), x));
        ok = false;
      }
      f.value[k] = x;
    }
  }
  if (!ok) return std::nullopt;
  return f;
}

// The optional field `key` of r, as a vector of `variables`; `fallback` when absent or wrong.
inline vector_field vector_field_or(const object_reader& r, std::string_view key,
                                    const std::vector<std::string>& variables, const constant_table& constants,
                                    std::string_view example, const vec2& fallback = vec2::Zero()) {
  vector_field f{fallback, {}, r.at(key)};
  if (const json* v = r.find(key))
    if (auto read = to_vector_field(r.diag(), *v, r.at(key), variables, constants, example)) f = std::move(*read);
  return f;
}

}  // namespace rkpm::runner::case_file
