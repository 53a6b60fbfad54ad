#pragma once
// The isotropic hardening laws of J2 plasticity (docs/method.md section 4.3), one header each,
// and `laws`, the list every consumer reads: the case files take any law of it by name with its
// `parameters()` (tools/runner/case_file/case_material.hpp), and the tests check each against
// its closed forms. A new law is one header here, one entry in `laws`, and its test.
//   linear:    sigma_y = sigma_y0 + H eps_p                            (23)
//   power_law: sigma_y = K (eps0 + eps_p)^n                            (24)
//   voce:      sigma_y = sigma_0 + Q (1 - exp(-b eps_p)) + H eps_p     (24a)

#include <boost/hana/tuple.hpp>
#include <boost/hana/type.hpp>

#include <rkpm/material/hardening/linear.hpp>
#include <rkpm/material/hardening/power_law.hpp>
#include <rkpm/material/hardening/voce.hpp>

namespace rkpm::material::hardening {

inline constexpr auto laws = boost::hana::tuple_t<linear, power_law, voce>;

}  // namespace rkpm::material::hardening
