#pragma once
// The paper's materials (docs/method.md sections 10.1 and 10.3) for the material tests, with
// copper's moduli written in closed form so that the tests do not lean on the accessors of
// elastic_constants they check.

#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/material/hardening.hpp>

namespace rkpm::test::paper_materials {

inline const material::elastic_constants copper{117e9, 0.35, 8930.0};
inline const material::elastic_constants aluminium{71e9, 0.3, 2700.0};
inline const material::hardening::linear copper_hardening{400e6, 100e6};
inline const material::hardening::power_law wheel_hardening{576.79e6, 0.01658, 0.3593};

inline constexpr double copper_mu = 117e9 / (2.0 * (1.0 + 0.35));
inline constexpr double copper_K = 117e9 / (3.0 * (1.0 - 2.0 * 0.35));
inline constexpr double copper_lambda = copper_K - 2.0 * copper_mu / 3.0;

}  // namespace rkpm::test::paper_materials
