#pragma once
// Reading one entry of "bodies": its shape (rectangle, polygon or Gmsh mesh), material,
// initial velocity and body force (numbers or expressions: read_expressions.hpp), edge
// constraints and contact slaves. Values are checked one by
// one here (types, signs, ranges); what needs the whole body (a polygon with no area, an edge
// name, a tool inside it) is checked in cross_checks.hpp.

#include <algorithm>
#include <array>
#include <boost/hana.hpp>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include <rkpm/material/elastic.hpp>
#include <rkpm/material/hardening.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/material/zerilli_armstrong.hpp>

#include "case_description.hpp"
#include "json_fields.hpp"
#include "read_expressions.hpp"

namespace rkpm::runner::case_file {

namespace detail {

inline std::optional<body_shape> read_shape(diagnostics& d, const json& value, const std::string& at,
                                            const std::filesystem::path& folder) {
  static constexpr std::array<std::string_view, 3> kinds{"rectangle", "polygon", "mesh"};
  object_reader shape(d, value, at, {kinds.begin(), kinds.end()});
  if (!shape.valid()) return std::nullopt;
  if (value.size() != 1) {
    d.error(at, fmt::format("give exactly one of {} (found {})", list_choices(kinds), value.size()));
    return std::nullopt;
  }
  const std::string kind = value.begin().key();
  if (kind == "rectangle") {
    object_reader r(d, value[kind], shape.at(kind), {"lower_left_m", "upper_right_m", "particles"});
    const auto lo = r.point("lower_left_m", "[0, 0]");
    const auto hi = r.point("upper_right_m", "[3.2e-3, 32.4e-3]");
    rectangle_shape s;
    if (const json* n = r.required("particles", "[21, 51]")) {
      const bool pair = n->is_array() && n->size() == 2;
      const auto nx = pair ? to_integer(d, (*n)[0], child_pointer(r.at("particles"), 0), "21") : std::nullopt;
      const auto ny = pair ? to_integer(d, (*n)[1], child_pointer(r.at("particles"), 1), "51") : std::nullopt;
      if (!pair)
        d.error(r.at("particles"),
                fmt::format("expected [particles along x, along y], got {}; give e.g. [21, 51]", describe(*n)));
      for (int k = 0; k < 2; ++k) {
        const auto c = k == 0 ? nx : ny;
        if (c && *c < 2)
          d.error(child_pointer(r.at("particles"), k),
                  fmt::format("{} particles: a grid needs at least 2 per direction", *c));
        if (c) s.particles[k] = *c;
      }
      if (!nx || !ny || *nx < 2 || *ny < 2) return std::nullopt;
    }
    if (!lo || !hi) return std::nullopt;
    s.lower_left = *lo;
    s.upper_right = *hi;
    return s;
  }
  if (kind == "polygon") {
    object_reader p(d, value[kind], shape.at(kind), {"vertices_m", "spacing_m"});
    const json* v = p.required("vertices_m", "[[0, 0], [0.1, 0], [0, 0.1]]");
    const auto vertices = v ? to_points(d, *v, p.at("vertices_m"), 3, "[[0, 0], [0.1, 0], [0, 0.1]]") : std::nullopt;
    const auto spacing = p.number("spacing_m", "1e-3");
    if (spacing && !check_positive(d, p.at("spacing_m"), *spacing, "1e-3")) return std::nullopt;
    if (!vertices || !spacing) return std::nullopt;
    return polygon_shape{*vertices, *spacing};
  }
  object_reader m(d, value[kind], shape.at(kind), {"file"});
  const auto file = m.text("file", "plate.msh");
  if (!file) return std::nullopt;
  const std::filesystem::path path = folder / *file;
  if (!std::filesystem::is_regular_file(path)) {
    d.error(m.at("file"), fmt::format("mesh file '{}' does not exist (looked for {}); give a path relative to the "
                                      "case file's folder", *file, path.string()));
    return std::nullopt;
  }
  return mesh_shape{path};
}

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

inline material_description read_material(diagnostics& d, const json& value, const std::string& at) {
  const std::array<std::string_view, 4> laws{material::elastic::name, material::j2_name, material::johnson_cook::name,
                                             material::zerilli_armstrong::name};
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
  const bool j2 = law != material::elastic::name && !johnson_cook && !zerilli_armstrong;
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
  if (m.law != material::j2_name) return m;
  m.hardening = r.choice("hardening", hardenings, "hardening law", default_hardening).value_or("");
  if (unknown_hardening) return m;
  m.flow_law = read_hardening(d, r, m.hardening);
  return m;
}

inline std::optional<constraint_description> read_constraint(diagnostics& d, const json& value, const std::string& at) {
  object_reader r(d, value, at, {"edge", "velocity_m_s"});
  const auto edge = r.text("edge", "left");
  const json* v = r.required("velocity_m_s", "[0, null]");
  if (!edge || !v) return std::nullopt;
  constraint_description c{*edge, {}, at};
  const std::string vat = r.at("velocity_m_s");
  if (!v->is_array() || v->size() != 2) {
    d.error(vat, fmt::format("expected [vx, vy] with null for a free component, got {}; give e.g. [0, null]",
                             describe(*v)));
    return std::nullopt;
  }
  for (int k = 0; k < 2; ++k)
    if (!(*v)[k].is_null()) {
      const auto x = to_number(d, (*v)[k], child_pointer(vat, k), "0 (held) or null (free)");
      if (!x) return std::nullopt;
      c.velocity[k] = *x;
    }
  if (!c.velocity[0] && !c.velocity[1]) {
    d.error(vat, "both components are null, so this constrains nothing; give a velocity for one of them or "
                 "remove the constraint");
    return std::nullopt;
  }
  return c;
}

}  // namespace detail

inline body_description read_body(diagnostics& d, const json& value, const std::string& at,
                                   const std::filesystem::path& folder, const constant_table& constants = {}) {
  object_reader r(d, value, at, {"name", "shape", "material", "initial_velocity_m_s", "body_force_m_s2",
                                 "constraints", "slaves"});
  body_description b;
  b.at = at;
  if (!r.valid()) return b;
  b.name = r.text("name", "bar").value_or("");
  if (const json* s = r.required("shape", "{\"rectangle\": {...}}"))
    if (auto shape = detail::read_shape(d, *s, r.at("shape"), folder)) b.shape = std::move(*shape);
  if (const json* m = r.required("material", "{\"law\": \"j2\", ...}"))
    b.material = detail::read_material(d, *m, r.at("material"));
  b.initial_velocity = vector_field_or(r, "initial_velocity_m_s", position_variables(), constants,
                                       "[0, -190] or [\"-w * y\", \"w * x\"] (x, y: the reference position, m)");
  b.body_force = vector_field_or(r, "body_force_m_s2", position_time_variables(), constants,
                                 "[0, -9.81] or [\"0\", \"-9.81 * min(1, t / 1e-3)\"] (x, y in m, t in s)");
  if (const json* cs = r.find("constraints")) {
    if (!cs->is_array())
      d.error(r.at("constraints"), fmt::format("expected a list of constraints, got {}; give e.g. "
                                               "[{{\"edge\": \"left\", \"velocity_m_s\": [0, null]}}]", describe(*cs)));
    else
      for (std::size_t i = 0; i < cs->size(); ++i)
        if (auto c = detail::read_constraint(d, (*cs)[i], child_pointer(r.at("constraints"), i)))
          b.constraints.push_back(*c);
  }
  if (const json* s = r.find("slaves"); s && s->is_object()) {
    object_reader layers(d, *s, r.at("slaves"), {"layers"});
    const auto k = layers.integer("layers", "3");
    if (k && *k < 1)
      d.error(layers.at("layers"), fmt::format("{} layers; give at least 1 (1: the surface particles), or \"all\"", *k));
    else if (k)
      b.slave_layers = *k;
  } else {
    const std::array<std::string_view, 2> slaves{"boundary", "all"};
    b.slave_layers = r.choice("slaves", slaves, "slave choice", "boundary").value_or("boundary") == "all" ? 0 : 1;
  }
  return b;
}

}  // namespace rkpm::runner::case_file
