#pragma once
// Reading the "material" of an entry of "bodies": its law, its elastic constants and, for J2,
// its hardening law (any of material::hardening::laws, read by its parameters()); the
// Johnson-Cook and Zerilli-Armstrong laws' constants are read in read_temperature_laws.hpp, the
// Rankine law's (brittle fracture) here.
// Values are checked one by one (types, signs, ranges).

#include <algorithm>
#include <cmath>
#include <array>
#include <boost/hana.hpp>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include <rkpm/material/elastic.hpp>
#include <rkpm/material/hardening.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/material/rankine_fracture.hpp>
#include <rkpm/material/zerilli_armstrong.hpp>

#include "case_description.hpp"
#include "json_fields.hpp"
#include "read_temperature_laws.hpp"

namespace rkpm::runner::case_file::detail {

// The names of the hardening laws (material::hardening::laws), in the list's order.
inline std::vector<std::string_view> hardening_names() {
  std::vector<std::string_view> names;
  boost::hana::for_each(material::hardening::laws, [&](auto law) { names.push_back(decltype(law)::type::name); });
  return names;
}

// Every law's keys where `applies(law name)` holds, each once, in the list's order.
template <class Applies>
void add_hardening_keys(std::vector<std::string_view>& known, Applies applies) {
  boost::hana::for_each(material::hardening::laws, [&](auto law) {
    using law_type = typename decltype(law)::type;
    if (!applies(law_type::name)) return;
    for (const auto& p : law_type::parameters())
      if (std::find(known.begin(), known.end(), p.key) == known.end()) known.push_back(p.key);
  });
}

// The keys of "law": "rankine" (docs/method.md section 4.7), besides the elastic three.
inline constexpr std::array<std::string_view, 3> rankine_keys{"tensile_strength_Pa", "fracture_energy_J_m2",
                                                              "band_width_m"};

// The Rankine law's constants from r, each checked with a one-line error (the band width against
// the snap-back bound (103) once the body's particles are known, build_problem.hpp).
inline void read_rankine(diagnostics& d, const object_reader& r, material_description& m) {
  rankine_description k;
  bool ok = true;
  const auto positive = [&](std::string_view key, std::string_view example) -> double {
    const auto x = r.number(key, example);
    if (!x) {
      ok = false;
      return 0.0;
    }
    if (!(*x > 0.0 && std::isfinite(*x))) {
      d.error(r.at(key), fmt::format("{:g} must be positive; give e.g. {}", *x, example));
      ok = false;
    }
    return *x;
  };
  k.tensile_strength = positive("tensile_strength_Pa", "70e6 (PMMA)");
  k.fracture_energy = positive("fracture_energy_J_m2", "500 (PMMA)");
  if (r.find("band_width_m")) k.band_width = positive("band_width_m", "0.75 times the support radius (cubic kernel)");
  if (ok) m.rankine = k;
}

// The law named `name` with its constants read from r (each checked against its bound).
inline hardening_law read_hardening(diagnostics& d, const object_reader& r, std::string_view name) {
  hardening_law out;
  boost::hana::for_each(material::hardening::laws, [&](auto law) {
    using law_type = typename decltype(law)::type;
    if (law_type::name != name) return;
    law_type h{};
    for (const auto& p : law_type::parameters()) {
      const auto x = r.number(p.key, p.example);
      if (!x) continue;
      h.*p.value = *x;
      if (p.bound == material::hardening::lower_bound::positive) check_positive(d, r.at(p.key), *x, p.example);
      else check_non_negative(d, r.at(p.key), *x, p.example);
    }
    out = hardening_law::of(h);
  });
  return out;
}

inline material_description read_material(diagnostics& d, const json& value, const std::string& at) {
  const std::array<std::string_view, 5> laws{material::elastic::name, material::j2_name, material::johnson_cook::name,
                                             material::zerilli_armstrong::name, material::rankine_fracture::name};
  const std::vector<std::string_view> hardenings = hardening_names();
  const std::string_view default_hardening = hardenings.front();
  // The fields allowed depend on the law and hardening named, so look at those first.
  const auto peek = [&](const char* key) {
    return value.is_object() && value.contains(key) && value[key].is_string() ? value[key].get<std::string>() : "";
  };
  const std::string law = peek("law"), hardening = peek("hardening"), lattice = peek("lattice");
  // An unknown law may still be J2 misspelt: accept its fields rather than report each; an
  // unknown hardening law likewise accepts every law's fields.
  const bool johnson_cook = law == material::johnson_cook::name;
  const bool zerilli_armstrong = law == material::zerilli_armstrong::name;
  const bool rankine = law == material::rankine_fracture::name;
  const bool j2 = law != material::elastic::name && !johnson_cook && !zerilli_armstrong && !rankine;
  const bool unknown_hardening =
      !hardening.empty() && std::find(hardenings.begin(), hardenings.end(), hardening) == hardenings.end();
  std::vector<std::string_view> known{"law", "youngs_modulus_Pa", "poisson_ratio", "density_kg_m3"};
  if (j2) {
    known.push_back("hardening");
    add_hardening_keys(known, [&](std::string_view name) {
      return unknown_hardening || name == (hardening.empty() ? default_hardening : std::string_view(hardening));
    });
  }
  if (johnson_cook) known.insert(known.end(), johnson_cook_keys.begin(), johnson_cook_keys.end());
  if (rankine) known.insert(known.end(), rankine_keys.begin(), rankine_keys.end());
  if (zerilli_armstrong) {  // an unknown lattice accepts both lattices' keys
    known.insert(known.end(), zerilli_armstrong_keys.begin(), zerilli_armstrong_keys.end());
    known.push_back("melt_temperature_K");
    if (lattice != "bcc") known.insert(known.end(), zerilli_armstrong_fcc_keys.begin(), zerilli_armstrong_fcc_keys.end());
    if (lattice != "fcc") known.insert(known.end(), zerilli_armstrong_bcc_keys.begin(), zerilli_armstrong_bcc_keys.end());
  }
  object_reader r(d, value, at, known);
  material_description m;
  if (!r.valid()) return m;
  m.law = r.choice("law", laws, "material law").value_or("");
  if (const auto E = r.number("youngs_modulus_Pa", "117e9")) {
    m.youngs_modulus = *E;
    check_positive(d, r.at("youngs_modulus_Pa"), *E, "117e9 (copper)");
  }
  if (const auto nu = r.number("poisson_ratio", "0.35")) {
    m.poisson_ratio = *nu;
    if (!(*nu > -1.0 && *nu < 0.5))
      d.error(r.at("poisson_ratio"), fmt::format("{:g} is outside the open range (-1, 0.5); give e.g. 0.35 (0.5, "
                                                 "incompressible, needs a mixed formulation)", *nu));
  }
  if (const auto rho = r.number("density_kg_m3", "8930")) {
    m.density = *rho;
    check_positive(d, r.at("density_kg_m3"), *rho, "8930 (copper)");
  }
  if (m.law == material::johnson_cook::name) read_johnson_cook(d, r, m);
  if (m.law == material::zerilli_armstrong::name) read_zerilli_armstrong(d, r, m);
  if (m.law == material::rankine_fracture::name) read_rankine(d, r, m);
  if (m.law != material::j2_name) return m;
  m.hardening = r.choice("hardening", hardenings, "hardening law", default_hardening).value_or("");
  if (unknown_hardening) return m;
  m.flow_law = read_hardening(d, r, m.hardening);
  return m;
}

}  // namespace rkpm::runner::case_file::detail
