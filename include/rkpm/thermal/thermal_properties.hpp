#pragma once
// thermal_properties: a body's conductivity k (W/(m K)) and specific heat c_p (J/(kg K)) for heat
// conduction (docs/method.md section 5.9, (86)), constant or functions of the temperature in kelvin.
// The density is the mechanical body's: the heat capacity of particle I is c_p m_I with the lumped
// mass m_I of (38), (88). heat_conduction calls the functions from one thread (a parsed
// expression need not be thread-safe), k at every quadrature point and c_p at every particle.

#include <cmath>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>

namespace rkpm::thermal {

struct thermal_properties {
  double conductivity = 0.0;   // k, W/(m K); used when conductivity_of_T is empty
  double specific_heat = 0.0;  // c_p, J/(kg K); used when specific_heat_of_T is empty
  std::function<double(double)> conductivity_of_T;  // optional k(T), T in K
  std::function<double(double)> specific_heat_of_T;  // optional c_p(T), T in K

  bool temperature_dependent() const { return conductivity_of_T || specific_heat_of_T; }
  bool capacity_depends_on_T() const { return static_cast<bool>(specific_heat_of_T); }

  // k and c_p at temperature T (K); a function that returns a negative, zero (c_p) or non-finite
  // value is refused with the temperature (`body` names the body in the message).
  double k(double T, std::string_view body = "a body") const {
    if (!conductivity_of_T) return conductivity;
    const double v = conductivity_of_T(T);
    if (!(std::isfinite(v) && v >= 0.0))
      fail("thermal properties of {}: the conductivity function gives {:.6g} W/(m K) at T = {:.6g} K: it must be "
           "finite and not negative there (check the expression and that temperatures are in kelvin)",
           body, v, T);
    return v;
  }
  double c_p(double T, std::string_view body = "a body") const {
    if (!specific_heat_of_T) return specific_heat;
    const double v = specific_heat_of_T(T);
    if (!(std::isfinite(v) && v > 0.0))
      fail("thermal properties of {}: the specific heat function gives {:.6g} J/(kg K) at T = {:.6g} K: it must be "
           "finite and positive there (check the expression and that temperatures are in kelvin)",
           body, v, T);
    return v;
  }

  // One line naming the problem and the fix.
  void validate(std::string_view body = "a body") const {
    if (!conductivity_of_T && !(std::isfinite(conductivity) && conductivity >= 0.0))
      fail("thermal properties of {}: the conductivity {:.6g} W/(m K) is negative or not a number: give k >= 0 in "
           "W/(m K) (steel about 45, copper about 400)",
           body, conductivity);
    if (!specific_heat_of_T && !(std::isfinite(specific_heat) && specific_heat > 0.0))
      fail("thermal properties of {}: the specific heat {:.6g} J/(kg K) must be positive and finite: give c_p > 0 "
           "in J/(kg K) (steel about 460, copper about 385)",
           body, specific_heat);
  }
};

// The properties of each body of a model (model_bodies' numbering), validated, with the names the
// messages give them ("body 1").
class body_properties {
 public:
  body_properties() = default;
  explicit body_properties(std::vector<thermal_properties> bodies) : props_(std::move(bodies)) {
    for (std::size_t b = 0; b < props_.size(); ++b) {
      names_.push_back(fmt::format("body {}", b));
      props_[b].validate(names_[b]);
      k_of_T_ = k_of_T_ || static_cast<bool>(props_[b].conductivity_of_T);
    }
  }
  std::size_t size() const { return props_.size(); }
  bool conductivity_depends_on_T() const { return k_of_T_; }
  bool capacity_depends_on_T(std::size_t b) const { return props_[b].capacity_depends_on_T(); }
  double k(std::size_t b, double T) const { return props_[b].k(T, names_[b]); }
  double c_p(std::size_t b, double T) const { return props_[b].c_p(T, names_[b]); }

 private:
  std::vector<thermal_properties> props_;
  std::vector<std::string> names_;
  bool k_of_T_ = false;
};

}  // namespace rkpm::thermal
