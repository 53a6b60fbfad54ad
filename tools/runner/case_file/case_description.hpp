#pragma once
// case_description: a case file (cases/*.json; the schema is in tools/runner/case_file/README.md) read
// and checked, as plain typed structs. Lengths, velocities and moduli are SI, as the file
// gives them. Every struct keeps the JSON pointer it was read from (`at`), so that a check
// made later (building at a resolution, naming a tool) still points at the line to fix.

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <rkpm/solver/mass_scaling.hpp>
#include <rkpm/solver/rereference.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/gmsh_body.hpp>

#include "../json.hpp"
#include "case_material.hpp"
#include "heat_description.hpp"

namespace rkpm::runner::case_file {

// Policy names exactly as the policies' ::name (tools/runner/methods.hpp lists the choices).
struct method_choice {
  std::string kernel, correction, quadrature, contact;
};

// The file's "constants": {"w": 100}, named numbers the expressions may use.
using constant_table = std::map<std::string, double, std::less<>>;

// A vector given per body or per tool: two numbers, or, per component, a number or an
// expression (a string) of the field's variables and the file's constants (expressions.hpp).
// An expression that names no variable ("-190", "2 * w") is read as the number it gives, so that
// ["0", "-190"] runs exactly as [0, -190].
struct vector_field {
  vec2 value = vec2::Zero();              // the numbers (0 where an expression gives the component)
  std::array<std::string, 2> expression;  // "" where the component is a number
  std::string at;                         // the JSON pointer of the pair
  bool varies() const { return !expression[0].empty() || !expression[1].empty(); }
  bool operator==(const vector_field& o) const { return value == o.value && expression == o.expression; }
};

// ---- bodies -----------------------------------------------------------------------------
struct rectangle_shape {  // a regular grid, as make_grid_particles / make_grid_mesh build it
  vec2 lower_left = vec2::Zero(), upper_right = vec2::Zero();
  std::array<int, 2> particles{2, 2};  // along x and y at resolution 1
};
struct polygon_shape {  // counter-clockwise, simple; meshed with a target spacing
  std::vector<vec2> vertices;
  double spacing = 0.0;  // at resolution 1
};
struct mesh_shape {  // a Gmsh file, used as given
  std::filesystem::path file;  // resolved against the case file's folder
  io::gmsh_body body;          // read by load_case_file (its node groups name the edges)
  int meshed_at = 1;           // the resolution a .geo script was meshed at (a .msh file: 1)
};
using body_shape = std::variant<rectangle_shape, polygon_shape, mesh_shape>;

// "law": "rankine": brittle fracture (material::rankine_fracture); the band width, when not
// given, follows the body's particles (build_problem.hpp).
struct rankine_description {
  double tensile_strength = 0.0;    // Pa
  double fracture_energy = 0.0;     // J/m^2
  std::optional<double> band_width;  // m
};

struct material_description {
  std::string law;        // "elastic", "j2", "johnson_cook", "zerilli_armstrong" or "rankine"
  std::string hardening;  // for j2: a law's ::name in material::hardening::laws ("linear", ...)
  double youngs_modulus = 0.0, poisson_ratio = 0.0, density = 0.0;
  hardening_law flow_law;  // for j2: that law with the file's constants (never yields otherwise)
  std::optional<material::johnson_cook> johnson_cook;  // for johnson_cook: the whole material
  std::optional<material::zerilli_armstrong> zerilli_armstrong;  // for zerilli_armstrong: likewise
  std::optional<rankine_description> rankine;                    // for rankine: its constants
};

// Prescribed velocity components (m/s) of the particles on a named edge; empty = free.
struct constraint_description {
  std::string edge;
  std::array<std::optional<double>, 2> velocity;
  std::string at;
};

struct body_description {
  std::string name;
  body_shape shape;
  material_description material;
  vector_field initial_velocity;  // m/s; expressions of x, y (the reference position, m)
  vector_field body_force;        // acceleration, m/s^2; expressions of x, y and t (s)
  std::vector<constraint_description> constraints;
  // "slaves": "boundary" (1), "all" (0) or {"layers": K}: the particles within K cell layers of
  // the surface (discretization/boundary_chains.hpp surface_layers).
  int slave_layers = 1;
  std::string at;
};

// Two deformable bodies in contact, by name: the slave body's slave particles against the
// master body's surface (contact/body_contact.hpp).
struct body_pair_description {
  std::string slave, master;
  std::string at;
};

// ---- tools ------------------------------------------------------------------------------
struct tool_motion_description {
  std::string type = "fixed";  // "fixed", "constant_velocity", "velocity_table", "velocity_expression"
  vec2 velocity = vec2::Zero();  // constant_velocity
  // velocity_expression: the velocity (m/s) as expressions of t (s); the displacement is its
  // integral from t = 0 (expression_motion.hpp).
  vector_field velocity_expression;
  // velocity_table rows: t (s, first 0, increasing), vx, vy (m/s); linear between rows,
  // constant after the last.
  std::vector<std::array<double, 3>> table;
};

struct tool_description {
  std::string name;
  std::vector<vec2> polyline;  // at t = 0
  bool body_on_left = true;
  tool_motion_description motion;
  double contact_depth = 0.0;  // 0: half the shortest segment (rigid_tool's default)
  std::string at;
};

// ---- histories --------------------------------------------------------------------------
// The measures recorded over time and at the end (summary.json "results").
struct extent_history {  // max/min/width of the particles' current x or y
  std::string body, of;  // of: max_x, min_x, max_y, min_y, width_x, width_y
  std::string on_edge;   // only particles that started on this edge ("" = all)
  // Only particles currently strictly beyond these bounds (NaN = no bound).
  double x_below = NAN, x_above = NAN, y_below = NAN, y_above = NAN;
};
struct tool_gap_history {  // (lowest `to` vertex - highest `from` vertex) along component, at time t
  std::string from, to;
  int component = 1;
};
struct tool_force_history {  // the tool's reaction, averaged over the last output interval
  std::string tool;
  int component = 1;
  bool absolute = false;
};
struct tool_displacement_history {
  std::string tool;
  int component = 1;
};
struct probe_history {  // the particle nearest to a reference point
  std::string body, quantity;  // quantity: position, displacement, velocity
  vec2 point = vec2::Zero();
  int component = 0;
};
struct max_plastic_strain_history { std::string body; };
struct max_temperature_history { std::string body; };  // K, of a "johnson_cook" or "zerilli_armstrong" body
struct failed_fraction_history { std::string body; };
struct max_penetration_history {};
struct volume_change_history { std::string body; };  // sum J w / sum w - 1
struct momentum_history {  // sum_I m_I v_I over the body's particles (N s, per metre in plane strain)
  std::string body;
  int component = 1;
};

using history_kind = std::variant<extent_history, tool_gap_history, tool_force_history, tool_displacement_history,
                                  probe_history, max_plastic_strain_history, max_penetration_history,
                                  volume_change_history, momentum_history, max_temperature_history,
                                  failed_fraction_history>;

struct history_description {
  std::string name;
  history_kind kind;
  double scale = 1.0;  // the value is multiplied by it (1e3: m -> mm)
  std::string at;
};

// ---- the case -----------------------------------------------------------------------------
struct case_description {
  std::filesystem::path file;  // for messages and relative paths
  json document;               // the file with the overrides applied, for summary.json
  std::string name, description;
  constant_table constants;    // "constants": named numbers the expressions may use
  std::string geometry;        // "plane_strain" or "axisymmetric"
  method_choice method;
  double support_factor = 2.0;
  double end_time = 0.0;
  std::vector<body_description> bodies;  // one or more, numbered in the file's order
  std::vector<tool_description> tools;
  std::vector<body_pair_description> body_pairs;  // "contact": {"pairs": [...]}
  bool two_pass = false;  // each pair also with the roles swapped
  bool self_contact = false;  // "contact": {"self": true}: every body against every body, itself included
  double friction = 0.0;
  std::optional<double> penalty_stiffness;  // N/m; needed by the penalty enforcement only
  int snapshots = 20, history_rows = 400;
  rereference_policy rereference;  // "rereference": {"max_stretch": 1.8} or {"every_steps": 50}, "rebalance_above"
  mass_scaling_policy mass_scaling;  // "mass_scaling": {"factor": 100} or {"target_dt_s": 2e-6}
  heat_description heat;             // "heat": conduction coupled to the run (read_heat.hpp)
  std::vector<history_description> histories;
};

// Whether a body of the file carries a temperature (Johnson-Cook or Zerilli-Armstrong) or a
// damage (Johnson-Cook, Rankine), so that its run needs material_type's state (case_material.hpp).
inline bool uses_johnson_cook_state(const case_description& c) {
  return c.heat.enabled || std::ranges::any_of(c.bodies, [](const body_description& b) {
    return b.material.johnson_cook.has_value() || b.material.zerilli_armstrong.has_value() ||
           b.material.rankine.has_value();
  });
}

}  // namespace rkpm::runner::case_file
