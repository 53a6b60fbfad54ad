#pragma once
// Reading the laws of a case file's material whose flow stress depends on the temperature and
// the strain rate, besides the elastic three constants (read_material.hpp): "law":
// "johnson_cook" (docs/method.md section 4.5, with its damage) and "law": "zerilli_armstrong"
// (section 4.6). Every constant is checked here with a one-line error, so that the library's own
// checks never fire.

#include <array>
#include <limits>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include <rkpm/material/elastic_constants.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/material/zerilli_armstrong.hpp>

#include "case_description.hpp"
#include "json_fields.hpp"

namespace rkpm::runner::case_file::detail {

// The keys of "law": "johnson_cook" (docs/method.md section 4.5), besides the elastic three.
inline constexpr std::array<std::string_view, 12> johnson_cook_keys{
    "A_Pa", "B_Pa", "n", "C", "reference_strain_rate_1_s", "m", "room_temperature_K", "melt_temperature_K",
    "specific_heat_J_kgK", "taylor_quinney", "initial_temperature_K", "damage"};

// A Johnson-Cook material from r (its elastic constants already read into m): every constant
// checked here with a one-line error, so that the library's own checks never fire.
inline void read_johnson_cook(diagnostics& d, const object_reader& r, material_description& m) {
  bool ok = true;
  // A required number in [lo, hi] (open at lo when `open`), reported with its fix.
  const auto get = [&](std::string_view key, std::string_view example, double lo, double hi, bool open,
                       std::string_view range) -> double {
    const auto x = r.number(key, example);
    if (!x) {
      ok = false;
      return 0.0;
    }
    if (!((open ? *x > lo : *x >= lo) && *x <= hi)) {
      d.error(r.at(key), fmt::format("{:g} is outside {}; give e.g. {}", *x, range, example));
      ok = false;
    }
    return *x;
  };
  const double inf = std::numeric_limits<double>::infinity();
  material::hardening::johnson_cook flow{};
  flow.A = get("A_Pa", "90e6 (OFHC copper)", 0.0, inf, false, "[0, inf): A must not be negative");
  flow.B = get("B_Pa", "292e6 (OFHC copper)", 0.0, inf, false, "[0, inf): B must not be negative");
  flow.n = get("n", "0.31 (OFHC copper)", 0.0, 1.0, true, "(0, 1]");
  flow.C = get("C", "0.025 (OFHC copper)", 0.0, inf, false, "[0, inf): C must not be negative");
  flow.reference_rate = get("reference_strain_rate_1_s", "1", 0.0, inf, true, "(0, inf): the rate must be positive");
  flow.m = get("m", "1.09 (OFHC copper)", 0.0, inf, true, "(0, inf): m must be positive");
  flow.room_temperature = get("room_temperature_K", "294", 0.0, inf, true, "(0, inf) K");
  flow.melt_temperature = get("melt_temperature_K", "1356 (copper)", 0.0, inf, true, "(0, inf) K");
  if (ok && !(flow.melt_temperature > flow.room_temperature)) {
    d.error(r.at("melt_temperature_K"), fmt::format("{:g} K is not above room_temperature_K = {:g} K; give the melting "
                                                    "point, e.g. 1356 (copper)",
                                                    flow.melt_temperature, flow.room_temperature));
    ok = false;
  }
  if (ok && !(flow.A + flow.B > 0.0)) {
    d.error(r.at("A_Pa"), "A and B are both 0: the flow stress would be 0; give e.g. \"A_Pa\": 90e6, \"B_Pa\": 292e6");
    ok = false;
  }
  material::johnson_cook_heating heat{};
  heat.specific_heat = get("specific_heat_J_kgK", "383 (copper)", 0.0, inf, true, "(0, inf) J/(kg K)");
  heat.taylor_quinney = r.number_or("taylor_quinney", 0.9);
  if (r.find("taylor_quinney") && !(heat.taylor_quinney >= 0.0 && heat.taylor_quinney <= 1.0)) {
    d.error(r.at("taylor_quinney"), fmt::format("{:g} is outside [0, 1], the fraction of plastic work turned into "
                                                "heat; give e.g. 0.9 (or leave it out: 0.9)", heat.taylor_quinney));
    ok = false;
  }
  heat.initial_temperature = r.number_or("initial_temperature_K", flow.room_temperature);
  if (r.find("initial_temperature_K") && !(heat.initial_temperature > 0.0)) {
    d.error(r.at("initial_temperature_K"), fmt::format("{:g} K must be positive; give e.g. 294 (or leave it out: the "
                                                       "room temperature)", heat.initial_temperature));
    ok = false;
  }
  std::optional<material::johnson_cook_damage> damage;
  if (const json* v = r.find("damage")) {
    object_reader dr(d, *v, r.at("damage"), {"D1", "D2", "D3", "D4", "D5", "opens_cracks"});
    if (dr.valid()) {
      const auto D1 = dr.number("D1", "0.54 (OFHC copper)"), D2 = dr.number("D2", "4.89 (OFHC copper)"),
                 D3 = dr.number("D3", "-3.03 (OFHC copper)"), D4 = dr.number("D4", "0.014 (OFHC copper)"),
                 D5 = dr.number("D5", "1.12 (OFHC copper)");
      // Whether a point that fails in tension cuts its cell (docs/method.md (32f), section 5.12).
      const bool opens_cracks = dr.boolean_or("opens_cracks", false);
      if (D1 && D2 && D3 && D4 && D5) damage = material::johnson_cook_damage{*D1, *D2, *D3, *D4, *D5, opens_cracks};
    }
    if (!damage) ok = false;
  }
  if (!ok || !d.empty()) return;
  try {
    m.johnson_cook.emplace(material::elastic_constants{m.youngs_modulus, m.poisson_ratio, m.density}, flow, heat, damage);
  } catch (const rkpm::error& e) {  // not expected: every constant was checked above
    d.error(r.pointer(), e.what());
  }
}

// The keys of "law": "zerilli_armstrong" (docs/method.md section 4.6) besides the elastic three:
// those of both lattices, and of each (an fcc file may not give bcc's constants, nor the reverse).
inline constexpr std::array<std::string_view, 8> zerilli_armstrong_keys{
    "lattice", "C0_Pa", "C3_1_K", "C4_1_K", "reference_strain_rate_1_s", "specific_heat_J_kgK", "taylor_quinney",
    "initial_temperature_K"};
inline constexpr std::array<std::string_view, 1> zerilli_armstrong_fcc_keys{"C2_Pa"};
inline constexpr std::array<std::string_view, 3> zerilli_armstrong_bcc_keys{"C1_Pa", "C5_Pa", "n"};

// A Zerilli-Armstrong material from r (its elastic constants already read into m): every
// constant checked here with a one-line error, so that the library's own checks never fire.
inline void read_zerilli_armstrong(diagnostics& d, const object_reader& r, material_description& m) {
  using flow_type = material::hardening::zerilli_armstrong;
  static constexpr std::array<std::string_view, 2> lattices{"fcc", "bcc"};
  const auto lattice = r.choice("lattice", lattices, "lattice");
  if (!lattice) return;
  const bool fcc = *lattice == "fcc";
  bool ok = true;
  // A required number, >= 0 or > 0, reported with its fix.
  const auto get = [&](std::string_view key, std::string_view example, bool positive) -> double {
    const auto x = r.number(key, example);
    if (!x) {
      ok = false;
      return 0.0;
    }
    if (!(positive ? check_positive(d, r.at(key), *x, example) : check_non_negative(d, r.at(key), *x, example)))
      ok = false;
    return *x;
  };
  flow_type flow{fcc ? flow_type::lattice_type::fcc : flow_type::lattice_type::bcc, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  flow.C0 = get("C0_Pa", fcc ? "65e6 (OFHC copper)" : "50e6", false);
  if (fcc) {
    flow.C2 = get("C2_Pa", "890e6 (OFHC copper)", false);
  } else {
    flow.C1 = get("C1_Pa", "1033e6 (Armco iron)", false);
    flow.C5 = get("C5_Pa", "266e6 (Armco iron)", false);
    flow.n = get("n", "0.289 (Armco iron)", true);
  }
  flow.C3 = get("C3_1_K", fcc ? "0.0028 (OFHC copper)" : "0.00698 (Armco iron)", false);
  flow.C4 = get("C4_1_K", fcc ? "0.000115 (OFHC copper)" : "0.000415 (Armco iron)", false);
  if (ok && !(flow.C0 + (fcc ? flow.C2 : flow.C1 + flow.C5) > 0.0)) {
    d.error(r.at("C0_Pa"), fcc ? "C0 and C2 are both 0: the flow stress would be 0; give e.g. \"C0_Pa\": 65e6, "
                                 "\"C2_Pa\": 890e6"
                               : "C0, C1 and C5 are all 0: the flow stress would be 0; give e.g. \"C1_Pa\": 1033e6, "
                                 "\"C5_Pa\": 266e6");
    ok = false;
  }
  flow.reference_rate = r.number_or("reference_strain_rate_1_s", 1.0);
  if (r.find("reference_strain_rate_1_s") && !check_positive(d, r.at("reference_strain_rate_1_s"), flow.reference_rate,
                                                             "1 (or leave it out: 1 /s)"))
    ok = false;
  material::zerilli_armstrong_heating heat{};
  heat.specific_heat = get("specific_heat_J_kgK", "383 (copper)", true);
  heat.taylor_quinney = r.number_or("taylor_quinney", 0.9);
  if (r.find("taylor_quinney") && !(heat.taylor_quinney >= 0.0 && heat.taylor_quinney <= 1.0)) {
    d.error(r.at("taylor_quinney"), fmt::format("{:g} is outside [0, 1], the fraction of plastic work turned into "
                                                "heat; give e.g. 0.9 (or leave it out: 0.9)", heat.taylor_quinney));
    ok = false;
  }
  heat.initial_temperature = get("initial_temperature_K", "294", true);
  if (r.find("melt_temperature_K")) {
    flow.melt_temperature = r.number_or("melt_temperature_K", flow.melt_temperature);
    if (ok && !(flow.melt_temperature > heat.initial_temperature)) {
      d.error(r.at("melt_temperature_K"), fmt::format("{:g} K is not above initial_temperature_K = {:g} K (the body "
                                                      "would start molten); give the melting point, e.g. 1356 "
                                                      "(copper), or leave it out (no melt)",
                                                      flow.melt_temperature, heat.initial_temperature));
      ok = false;
    }
  }
  if (!ok || !d.empty()) return;
  try {
    m.zerilli_armstrong.emplace(material::elastic_constants{m.youngs_modulus, m.poisson_ratio, m.density}, flow, heat);
  } catch (const rkpm::error& e) {  // not expected: every constant was checked above
    d.error(r.pointer(), e.what());
  }
}

}  // namespace rkpm::runner::case_file::detail
