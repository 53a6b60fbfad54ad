#pragma once
// body_forces: the external force f_ext,I = m_I g(X_I, t) at the particles (docs/method.md (39)),
// from the problem's constant body force or its body_force_field (solver/problem.hpp). A constant
// g is not stored; a field is evaluated at each step's end t(n+1) for (43), keeping the value at
// t(n) for the work of f_ext over the step, 1/2 (f_ext^n + f_ext^n+1) in (67).

#include <functional>
#include <utility>
#include <vector>

#include <rkpm/core/types.hpp>

namespace rkpm {

class body_forces {
 public:
  using field_type = std::function<vec2(const vec2& X, double t)>;

  body_forces() = default;
  // `X`, `mass`: the particles' reference positions and lumped masses (t = 0 for a field).
  body_forces(vec2 constant, field_type field, const std::vector<vec2>& X, const std::vector<double>& mass)
      : constant_(constant), field_(std::move(field)) {
    if (!field_) return;
    now_.resize(X.size());
    evaluate(0.0, X, mass);
    before_ = now_;
  }

  // f_ext,I at the time of the last advance (a constant body force: at any time).
  vec2 at(index_t I, const std::vector<double>& mass) const { return field_ ? now_[I] : vec2(mass[I] * constant_); }
  // f_ext,I over the step just advanced, for its work: the mean of f_ext(n) and f_ext(n+1).
  vec2 over_step(index_t I, const std::vector<double>& mass) const {
    return field_ ? vec2(0.5 * (before_[I] + now_[I])) : vec2(mass[I] * constant_);
  }
  // To the step's end t(n+1), keeping f_ext(n); nothing to do for a constant body force.
  void advance(double t, const std::vector<vec2>& X, const std::vector<double>& mass) {
    if (!field_) return;
    std::swap(before_, now_);
    evaluate(t, X, mass);
  }
  // After a checkpoint is read: the field is a function of t and not saved.
  void restore(double t, const std::vector<vec2>& X, const std::vector<double>& mass) {
    if (field_) evaluate(t, X, mass);
  }

 private:
  // On one thread: the field is the caller's function, which need not be thread-safe.
  void evaluate(double t, const std::vector<vec2>& X, const std::vector<double>& mass) {
    for (std::size_t I = 0; I < X.size(); ++I) now_[I] = mass[I] * field_(X[I], t);
  }

  vec2 constant_ = vec2::Zero();
  field_type field_;
  std::vector<vec2> now_, before_;  // with a field: f_ext at t(n+1) and t(n)
};

}  // namespace rkpm
