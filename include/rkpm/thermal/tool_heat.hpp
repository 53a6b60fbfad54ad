#pragma once
// What the heat coupling (thermal/heat_coupling.hpp, docs/method.md 5.11) is told about the
// contacts, and what it books of them:
//   tool_heat        the tools' temperatures, the interface conductance, the body's share of the
//                    frictional heat on the tools
//   coupling_ledger  the heat flows of the coupling since the start, beside the conduction's
//                    ledger (thermal/heat_ledger.hpp)

#include <cmath>
#include <cstddef>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/thermal/thermal_boundary.hpp>

namespace rkpm::thermal {

// Heat exchanged with the rigid tools (100) and made by friction on them (99); the conductance
// applies between bodies in contact too.
struct tool_heat {
  std::vector<time_value> temperature;  // K, one per tool (empty: no conduction to the tools)
  double conductance = 0.0;             // h_c, W/(m^2 K)
  double friction_to_body = 0.5;        // the share of the frictional heat that enters the body

  void validate(std::size_t tools) const {
    if (!temperature.empty() && temperature.size() != tools)
      fail("tool heat: {} tool temperatures for {} tools: give one per tool (or none)", temperature.size(), tools);
    if (!(conductance >= 0.0) || !std::isfinite(conductance))
      fail("tool heat: the interface conductance {} W/(m^2 K) must be finite and not negative", conductance);
    if (!(friction_to_body >= 0.0 && friction_to_body <= 1.0))
      fail("tool heat: the share of the frictional heat that enters the body, {}, must lie in [0, 1]",
           friction_to_body);
  }
};

// The heat flows of the coupling, J since the start, beside the conduction's ledger: plastic +
// friction_to_body + from_tools are its `sources`.
struct coupling_ledger {
  double plastic = 0.0;          // beta W_p (98)
  double friction = 0.0;         // made by friction (99), body and tools together
  double friction_to_body = 0.0;
  double from_tools = 0.0;       // conducted from the tools into the body (100)
  double between_bodies = 0.0;   // conducted from master bodies into slave bodies (100)
};

}  // namespace rkpm::thermal
