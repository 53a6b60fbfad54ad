#pragma once
// file_case<Geometry>: a case read from a JSON case file (tools/runner/case_file/README.md) in
// the shape simulate.hpp runs the typed cases in: its parameters are the checked
// case_description, its name and end time come from the file, build() and measure() are the
// case-file layer's. One type per geometry, since the geometry is a compile-time policy, and
// material state: case_file::j2_material for a file of J2 and elastic bodies,
// case_file::material_type for one with a Johnson-Cook body (case_file/case_material.hpp; the
// hardening law is chosen at run time, elastic is J2 that never yields), so that a file runs
// with any of its laws without a solver type per law.

#include <string>
#include <utility>
#include <vector>

#include <rkpm/core/types.hpp>
#include <rkpm/solver/problem.hpp>

#include "case_file/build_heat.hpp"
#include "case_file/build_problem.hpp"
#include "case_file/case_description.hpp"
#include "case_file/measure.hpp"
#include "case_traits.hpp"

namespace rkpm::runner {

template <class Geometry, class Material>
struct file_case {
  using parameters = case_file::case_description;
  using geometry_type = Geometry;
  using material_type = Material;

  static std::string name_of(const parameters& c) { return c.name; }
  static double end_time(const parameters& c) { return c.end_time; }

  template <class Contact>
  static problem<material_type, Contact> build(const parameters& c, int resolution) {
    return case_file::build_problem<Contact, material_type>(c, resolution);
  }

  // What runs beside the solver (the file's "heat"), attached once the solver is in its place and
  // before a checkpoint is read into it. Heat conduction runs on one process.
  template <class Solver>
  static void attach(Solver& s, const parameters& c, bool several_processes) {
    if (c.heat.enabled && several_processes)
      case_file::fail_at(c, c.heat.at, "heat conduction runs on one process: run without mpiexec, or without \"heat\"");
    case_file::attach_heat(s, c);
  }

  template <class Solver>
  static std::vector<std::pair<std::string, double>> measure(const Solver& s, const parameters& c,
                                                             const std::vector<vec2>& mean_tool_force) {
    return case_file::measure(s, c, mean_tool_force);
  }
  // The rows on several processes by reduction (row_reduction.hpp, case_file/measure_parts.hpp).
  template <class Solver>
  static std::vector<double> measure_maxima(const Solver& s, const parameters& c) {
    return case_file::measure_maxima(s, c);
  }
  template <class Solver>
  static std::vector<exact_sum> measure_sums(const Solver& s, const parameters& c) {
    return case_file::measure_sums(s, c);
  }
  template <class Solver>
  static std::vector<nearest_value> measure_nearest(const Solver& s, const parameters& c) {
    return case_file::measure_nearest(s, c);
  }
  template <class Solver>
  static std::vector<std::pair<std::string, double>> measure_from(const std::vector<double>& maxima,
                                                                  const std::vector<exact_sum>& sums,
                                                                  const std::vector<nearest_value>& nearest,
                                                                  const Solver& s, const parameters& c,
                                                                  const std::vector<vec2>& mean_tool_force) {
    return case_file::measure_from(maxima, sums, nearest, s, c, mean_tool_force);
  }
};

}  // namespace rkpm::runner
