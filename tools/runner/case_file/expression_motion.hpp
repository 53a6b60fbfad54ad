#pragma once
// The motion of a tool whose velocity is given as expressions of t ("type":
// "velocity_expression"): velocity(t) is the expression, displacement(t) its integral from 0,
// as the velocity table's displacement is its table's exact integral (make_tools.hpp). The
// solver moves the tool by displacement(t) and takes its velocity over a step as (u(t) - u(t -
// dt)) / dt (contact/tool_slave_contact.hpp), so the tool's position is the integral of the
// expression to quadrature accuracy whatever the steps.
//
// velocity_integral: u(t) by Gauss-Kronrod (15 points, boost::math::quadrature), bisected where
// its error estimate exceeds 1e-13 of the integral of |v| there (a kink such as min(1, t / T) is
// bisected down to round-off). The value is a function of t alone, not of the calls before, so a
// restarted run moves the tool exactly as the uninterrupted one: [0, t] is cut into panels of
// width h = 2^e, e = ilogb(t) - 9 (512 to 1023 whole panels before t), whose running sums are
// kept per e; a call integrates the whole panels once and then only its partial panel.
//
// The tool's motion is called between the parallel loops (one thread), yet a lock guards the
// expressions and the kept sums so that no caller has to know.

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <fmt/format.h>

#include <rkpm/contact/tool_motion.hpp>
#include <rkpm/core/error.hpp>

#include "case_description.hpp"
#include "vector_expression.hpp"

namespace rkpm::runner::case_file {

// u(t) = integral of v over [0, t]; for t < 0, v(0) t.
class velocity_integral {
 public:
  explicit velocity_integral(std::function<double(double)> v) : v_(std::move(v)) {}

  double operator()(double t) {
    if (t == 0.0) return 0.0;
    if (t < 0.0) return v_(0.0) * t;
    const int e = std::ilogb(t) - 9;
    if (e < -1000) return integrate(0.0, t, max_depth);  // below any time step
    const double h = std::ldexp(1.0, e);
    const auto whole = static_cast<std::size_t>(std::floor(t / h));  // exact: h is a power of 2
    std::vector<double>& sums = sums_[e];                             // sums[k]: over [0, k h]
    if (sums.empty()) sums.push_back(0.0);
    while (sums.size() <= whole) {
      const double a = static_cast<double>(sums.size() - 1) * h;
      sums.push_back(sums.back() + integrate(a, a + h, max_depth));
    }
    const double start = static_cast<double>(whole) * h;
    return sums[whole] + (t > start ? integrate(start, t, max_depth) : 0.0);
  }

 private:
  static constexpr int max_depth = 40;  // bisections: 2^-40 of a panel resolves any kink
  static constexpr double tolerance = 1e-13;

  double integrate(double a, double b, int depth) const {
    using rule = boost::math::quadrature::gauss_kronrod<double, 15>;
    double error = 0.0, l1 = 0.0;
    // Depth 0: the rule once, no bisection. Its error estimate is on [-1, 1], l1 on [a, b].
    const double q = rule::integrate(v_, a, b, 0, 0.0, &error, &l1);
    const double mid = 0.5 * (a + b);
    if (error * 0.5 * (b - a) <= tolerance * l1 || depth == 0 || !(mid > a && mid < b)) return q;
    return integrate(a, mid, depth - 1) + integrate(mid, b, depth - 1);
  }

  std::function<double(double)> v_;
  std::map<int, std::vector<double>> sums_;
};

// The tool motion of `velocity` (expressions of t); `file` names the case file in the error a
// velocity that is not finite at some t raises.
inline contact::tool_motion expression_motion(const vector_field& velocity, const constant_table& constants,
                                              const std::string& file) {
  struct state {
    state(vector_expression velocity, std::string case_file) : v(std::move(velocity)), file(std::move(case_file)) {}
    std::mutex lock;
    vector_expression v;
    std::string file;
    std::array<std::unique_ptr<velocity_integral>, 2> u;  // for the components that vary

    vec2 velocity(double t) const {  // under the lock
      const vec2 value = v(std::array{t});
      if (const auto bad = v.not_finite(value, fmt::format("t = {:.9g} s", t), "make it finite over the run"))
        throw rkpm::error(fmt::format("{}: {}: {}", file, bad->first, bad->second));
      return value;
    }
  };
  const auto s = std::make_shared<state>(vector_expression(velocity, time_variables(), constants), file);
  for (int k = 0; k < 2; ++k)
    if (!velocity.expression[k].empty())
      s->u[k] = std::make_unique<velocity_integral>([raw = s.get(), k](double t) { return raw->velocity(t)[k]; });
  return contact::tool_motion::prescribed(
      [s](double t) {
        const std::lock_guard<std::mutex> hold(s->lock);
        vec2 u;
        for (int k = 0; k < 2; ++k) u[k] = s->u[k] ? (*s->u[k])(t) : s->v.field().value[k] * t;
        return u;
      },
      [s](double t) {
        const std::lock_guard<std::mutex> hold(s->lock);
        return s->velocity(t);
      });
}

}  // namespace rkpm::runner::case_file
