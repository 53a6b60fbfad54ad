#pragma once
// What a case file's "heat" describes (read_heat.hpp reads it, build_heat.hpp builds it).

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rkpm::runner::case_file {

struct heat_body_description {
  std::optional<double> conductivity, specific_heat, initial_temperature, taylor_quinney;
  // k(T) and c_p(T) as expressions of T (K), in place of the numbers ("" when a number is given).
  std::string conductivity_of_T, specific_heat_of_T;
  std::string at;
};

struct heat_edge_description {
  std::string body, edge;
  std::string kind;  // "convection", "temperature" or "flux"
  double value = 0.0;  // T_inf (K), T (K) or q (W/m^2)
  double film_coefficient = 0.0;  // h, W/(m^2 K)
  std::string at;
};

struct heat_description {
  bool enabled = false;
  std::map<std::string, heat_body_description> bodies;  // by body name
  std::map<std::string, double> tool_temperature;       // K, by tool name
  std::map<std::string, std::string> tool_temperature_of_t;  // or an expression of t (s), by tool name
  double conductance = 0.0;                             // W/(m^2 K)
  double friction_to_body = 0.5;
  std::vector<heat_edge_description> edges;
  std::string at;
};

}  // namespace rkpm::runner::case_file
