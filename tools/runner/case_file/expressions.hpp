#pragma once
// Expressions in case files: a component of a vector given as a string instead of a number,
// "initial_velocity_m_s": ["-w * y", "w * x"], parsed and evaluated by muparser (Debian
// libmuparser-dev; its syntax and functions: https://beltoforion.de/en/muparser/) with the
// variables of the field it gives (x, y: the reference position, m; t: the time, s) and the
// file's named "constants". An expression is parsed once; each evaluation sets the variables
// and runs muparser's byte code. Evaluation writes into the expression's own variables, so one
// expression must not be evaluated from two threads at once (the callers evaluate at set-up,
// on one thread, or under a lock: expression_motion.hpp).

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <muParser.h>

#include <rkpm/core/types.hpp>

#include "case_description.hpp"
#include "diagnostics.hpp"

namespace rkpm::runner::case_file {

// The variables each field's expressions may name, in the order their values are given.
inline const std::vector<std::string>& position_variables() {  // initial_velocity_m_s
  static const std::vector<std::string> v{"x", "y"};
  return v;
}
inline const std::vector<std::string>& position_time_variables() {  // body_force_m_s2
  static const std::vector<std::string> v{"x", "y", "t"};
  return v;
}
inline const std::vector<std::string>& time_variables() {  // a tool's velocity_m_s
  static const std::vector<std::string> v{"t"};
  return v;
}
// Every variable of some field: no constant may take one of these names.
inline constexpr std::array<std::string_view, 3> variable_names{"x", "y", "t"};

// One expression of named variables, parsed by muparser.
class expression {
 public:
  // Parses `text`; on a syntax error or a name that is neither a variable nor a constant,
  // returns nullopt and says why in `why` ("...; fix it").
  static std::optional<expression> parse(const std::string& text, const std::vector<std::string>& variables,
                                         const constant_table& constants, std::string& why) {
    expression e;
    e.text_ = text;
    e.values_ = std::make_unique<double[]>(variables.size());
    e.count_ = variables.size();
    e.parser_ = std::make_unique<mu::Parser>();
    mu::Parser& p = *e.parser_;
    try {
      for (std::size_t k = 0; k < variables.size(); ++k) p.DefineVar(variables[k], &e.values_[k]);
      for (const auto& [name, value] : constants) p.DefineConst(name, value);
      p.SetExpr(text);
      // Parses, listing every name used as a variable, known or not.
      std::vector<std::string> unknown;
      for (const auto& [name, _] : p.GetUsedVar()) {
        if (std::find(variables.begin(), variables.end(), name) == variables.end()) unknown.push_back(name);
        else e.uses_variables_ = true;
      }
      if (!unknown.empty()) {
        std::string quoted;
        for (const auto& name : unknown) quoted += fmt::format("{}'{}'", quoted.empty() ? "" : ", ", name);
        why = fmt::format("the expression \"{}\" names {}, neither a variable here nor a constant; {}", text, quoted,
                          allowed_names(variables, constants));
        return std::nullopt;
      }
      e.value();  // the byte code, built once
    } catch (const mu::Parser::exception_type& error) {
      why = syntax_message(text, error);
      return std::nullopt;
    }
    return e;
  }

  const std::string& text() const { return text_; }
  // False for a number written as an expression ("-190", "2 * w"): it names no variable.
  bool uses_variables() const { return uses_variables_; }
  // The value at `values`, one per variable in the order parse was given them.
  double operator()(std::span<const double> values) const {
    for (std::size_t k = 0; k < count_ && k < values.size(); ++k) values_[k] = values[k];
    return value();
  }

 private:
  expression() = default;
  double value() const { return parser_->Eval(); }

  // "the names allowed here are the variables x, y and the constants w".
  static std::string allowed_names(const std::vector<std::string>& variables, const constant_table& constants) {
    std::vector<std::string> names;
    for (const auto& [name, _] : constants) names.push_back(name);
    const std::string given = names.empty() ? "" : "the constants " + list_choices(names);
    if (variables.empty())
      return given.empty() ? "no name is allowed here (no variable, and the file gives no \"constants\")"
                           : "the names allowed here are " + given + " (no variable)";
    return fmt::format("the names allowed here are the variables {}{}", list_choices(variables),
                       given.empty() ? " (the file gives no \"constants\")" : " and " + given);
  }

  // muparser's message, and where: "... at position 3" counts characters from 0.
  static std::string syntax_message(const std::string& text, const mu::Parser::exception_type& error) {
    std::string message = error.GetMsg();
    while (!message.empty() && (message.back() == '.' || message.back() == ' ')) message.pop_back();
    const int at = error.GetPos();
    std::string where;
    if (at >= 0 && static_cast<std::size_t>(at) <= text.size())
      where = at == 0 ? " (at its start)" : fmt::format(" (after \"{}\")", text.substr(0, static_cast<std::size_t>(at)));
    return fmt::format("the expression \"{}\" does not parse: {}{}; correct it there (muparser syntax: e.g. "
                       "\"-10 * min(1, t / 1e-4)\")", text, message, where);
  }

  std::string text_;
  std::unique_ptr<mu::Parser> parser_;  // holds pointers into values_: neither moves
  std::unique_ptr<double[]> values_;
  std::size_t count_ = 0;
  bool uses_variables_ = false;
};

// Why `name` cannot name a constant ("the constant 'x' has the name of a variable; ..."), or ""
// if it can.
inline std::string constant_name_problem(const std::string& name) {
  if (std::find(variable_names.begin(), variable_names.end(), name) != variable_names.end())
    return fmt::format("the constant '{}' has the name of a variable ({}); rename it", name, list_choices(variable_names));
  const bool identifier = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                          name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") ==
                              std::string::npos;
  if (!identifier)
    return fmt::format("'{}' cannot name a constant; use letters, digits and '_', not starting with a digit (e.g. "
                       "\"omega\")", name);
  const mu::Parser builtin;
  if (builtin.GetFunDef().count(name) || builtin.GetConst().count(name))
    return fmt::format("the constant '{}' has the name of one of muparser's own functions or constants; rename it",
                       name);
  return "";
}

}  // namespace rkpm::runner::case_file
