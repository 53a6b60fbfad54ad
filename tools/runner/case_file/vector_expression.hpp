#pragma once
// vector_expression: a vector_field (case_description.hpp) as a function of its variables, for
// building and running: each component its number, or its expression parsed once
// (expressions.hpp). Not for two threads at once (expressions.hpp says why).

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>

#include "case_description.hpp"
#include "diagnostics.hpp"
#include "expressions.hpp"

namespace rkpm::runner::case_file {

class vector_expression {
 public:
  // `variables` name the values operator() takes, in order. The field was read and checked by
  // load_case_file, so its expressions parse; if one does not, rkpm::error says why.
  vector_expression(vector_field field, const std::vector<std::string>& variables, const constant_table& constants)
      : field_(std::move(field)) {
    for (int k = 0; k < 2; ++k) {
      if (field_.expression[k].empty()) continue;
      std::string why;
      component_[k] = expression::parse(field_.expression[k], variables, constants, why);
      if (!component_[k]) fail("{}/{}: {}", field_.at, k, why);
    }
  }

  vec2 operator()(std::span<const double> values) const {
    vec2 v = field_.value;
    for (int k = 0; k < 2; ++k)
      if (component_[k]) v[k] = (*component_[k])(values);
    return v;
  }

  const vector_field& field() const { return field_; }

  // If v (a value of this field) is not finite: "POINTER/k", and "the expression "..." gives nan
  // at WHERE; FIX" for the first component that is not. nullopt if v is finite.
  std::optional<std::pair<std::string, std::string>> not_finite(const vec2& v, const std::string& where,
                                                                const std::string& fix) const {
    for (int k = 0; k < 2; ++k)
      if (!std::isfinite(v[k]))
        return std::pair{child_pointer(field_.at, static_cast<std::size_t>(k)),
                         fmt::format("the expression \"{}\" gives {} at {}; {}", field_.expression[k], v[k], where, fix)};
    return std::nullopt;
  }

 private:
  vector_field field_;
  std::array<std::optional<expression>, 2> component_;
};

}  // namespace rkpm::runner::case_file
