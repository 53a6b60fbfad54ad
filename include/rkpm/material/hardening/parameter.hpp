#pragma once
// hardening_parameter<Law>: one constant of a hardening law as the case files name it. Each law
// lists its constants (`static constexpr auto parameters()`), so that a case file reads any law
// of material::hardening::laws (material/hardening.hpp) without code of its own: the key (SI
// unit in its name), where the value goes, its lower bound and a typical value for messages.

#include <string_view>

namespace rkpm::material::hardening {

enum class lower_bound { positive, non_negative };

template <class Law>
struct hardening_parameter {
  std::string_view key;      // e.g. "yield_stress_Pa"
  double Law::*value;        // the member it sets
  lower_bound bound;         // > 0 or >= 0
  std::string_view example;  // shown when the key is missing or out of bounds, e.g. "400e6"
};

}  // namespace rkpm::material::hardening
