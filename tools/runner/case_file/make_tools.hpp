#pragma once
// The rigid tools of a case file as contact::rigid_tool, with their motions: fixed, constant
// velocity, a velocity table (linear between rows, constant after the last) whose
// displacement is its exact integral from t = 0, or a velocity given as expressions of t whose
// displacement is its integral to quadrature accuracy (expression_motion.hpp).

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/contact/rigid_tool.hpp>
#include <rkpm/contact/tool_motion.hpp>

#include "case_description.hpp"
#include "expression_motion.hpp"

namespace rkpm::runner::case_file {

// Rows (t_i, v_i) with t_0 = 0 < t_1 < ...; u_i = the displacement at t_i.
class velocity_table {
 public:
  explicit velocity_table(const std::vector<std::array<double, 3>>& rows) {
    for (const auto& r : rows) {
      if (!t_.empty()) u_.push_back(u_.back() + 0.5 * (r[0] - t_.back()) * (v_.back() + vec2(r[1], r[2])));
      else u_.push_back(vec2::Zero());
      t_.push_back(r[0]);
      v_.emplace_back(r[1], r[2]);
    }
  }

  vec2 velocity(double t) const {
    if (t <= t_.front()) return v_.front();
    if (t >= t_.back()) return v_.back();
    const std::size_t i = interval(t);
    const double s = (t - t_[i]) / (t_[i + 1] - t_[i]);
    return (1.0 - s) * v_[i] + s * v_[i + 1];
  }
  vec2 displacement(double t) const {
    if (t <= t_.front()) return v_.front() * t;
    if (t >= t_.back()) return u_.back() + (t - t_.back()) * v_.back();
    const std::size_t i = interval(t);
    return u_[i] + 0.5 * (t - t_[i]) * (v_[i] + velocity(t));
  }

 private:
  // The row i with t_i <= t < t_{i+1}.
  std::size_t interval(double t) const {
    return static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()) - 1;
  }
  std::vector<double> t_;
  std::vector<vec2> v_, u_;
};

// `constants` and `file`: for a velocity given as expressions (expression_motion.hpp).
inline contact::tool_motion make_motion(const tool_motion_description& m, const constant_table& constants = {},
                                        const std::string& file = "case file") {
  if (m.type == "constant_velocity") return contact::tool_motion::constant_velocity(m.velocity);
  if (m.type == "velocity_expression") {
    // Expressions that name no t are numbers (read_expressions.hpp): a constant velocity, exactly.
    if (!m.velocity_expression.varies()) return contact::tool_motion::constant_velocity(m.velocity_expression.value);
    return expression_motion(m.velocity_expression, constants, file);
  }
  if (m.type == "velocity_table") {
    const auto table = std::make_shared<const velocity_table>(m.table);
    return contact::tool_motion::prescribed([table](double t) { return table->displacement(t); },
                                            [table](double t) { return table->velocity(t); });
  }
  return contact::tool_motion::fixed();
}

inline std::vector<contact::rigid_tool> make_tools(const case_description& c) {
  std::vector<contact::rigid_tool> tools;
  for (const auto& t : c.tools)
    tools.emplace_back(t.name, t.polyline, t.body_on_left ? contact::side::left : contact::side::right,
                       make_motion(t.motion, c.constants, c.file.string()), t.contact_depth);
  return tools;
}

}  // namespace rkpm::runner::case_file
