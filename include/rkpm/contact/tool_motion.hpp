#pragma once
// tool_motion: the prescribed rigid translation u(t) of a tool (docs/method.md section 6.1: the
// master bodies are rigid tools with prescribed motion). Fixed, constant velocity, or any
// function of time; the function form is evaluated once per tool per step, so std::function
// costs nothing that matters.

#include <functional>
#include <utility>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm::contact {

class tool_motion {
 public:
  tool_motion() = default;  // fixed

  static tool_motion fixed() { return {}; }

  static tool_motion constant_velocity(const vec2& velocity) {
    if (!velocity.allFinite()) fail("tool motion: velocity is not finite; give a finite velocity in m/s");
    tool_motion m;
    m.velocity_ = velocity;
    return m;
  }

  // displacement(t) from the position at t = 0 (so displacement(0) should be zero) and its
  // derivative velocity(t).
  static tool_motion prescribed(std::function<vec2(double)> displacement,
                                std::function<vec2(double)> velocity) {
    if (!displacement || !velocity)
      fail("tool motion: prescribed motion needs both a displacement and a velocity function");
    tool_motion m;
    m.displacement_fn_ = std::move(displacement);
    m.velocity_fn_ = std::move(velocity);
    return m;
  }

  vec2 displacement(double t) const { return displacement_fn_ ? displacement_fn_(t) : vec2(velocity_ * t); }
  vec2 velocity(double t) const { return velocity_fn_ ? velocity_fn_(t) : velocity_; }

 private:
  vec2 velocity_ = vec2::Zero();
  std::function<vec2(double)> displacement_fn_;
  std::function<vec2(double)> velocity_fn_;
};

}  // namespace rkpm::contact
