// run_case_file: reads the case file (or, for --restart, the document the checkpoint kept),
// applies the command line's --set overrides, policies and end time, and runs it in its
// geometry, with the case-file material whose state its laws need (file_case_dispatch.hpp).
#include "run_case_file.hpp"

#include <algorithm>
#include <filesystem>

#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>

#include "case_file/load_case_file.hpp"

namespace rkpm::runner {

run_outcome run_case_file(const run_request& request) {
  run_request r = request;
  std::optional<restart_point> restart;
  case_file::case_description c;
  if (!r.restart.empty()) {
    restart = find_restart_point(r.restart);
    const json& d = restart->description;
    if (!d.contains("case_file"))
      fail("--restart {}: the checkpoint is of the built-in case {}: rkpm_run {} --restart {}", r.restart,
           d.at("case").get<std::string>(), d.at("case").get<std::string>(), r.restart);
    adopt_checkpoint_run(r, d, d.at("case").get<std::string>());
    // The problem as it was started, whatever the file says now.
    c = case_file::load_case_document(d.at("parameters"), d.at("case_file").get<std::string>(), {}, r.resolution);
    if (std::ranges::find(r.given, "--rebalance-above") == r.given.end())
      r.rereference.rebalance_above = c.rereference.rebalance_above;
    if (r.out_dir.empty()) r.out_dir = std::filesystem::absolute(restart->file).parent_path().string();
  } else {
    case_file::override_list overrides;
    for (const auto& [pointer, value] : r.sets) overrides.emplace_back(pointer, value);
    c = case_file::load_case_file(r.case_file, overrides, r.resolution);
    // The file's policies, unless the command line names others.
    auto given = [&](const char* option) { return std::ranges::find(r.given, option) != r.given.end(); };
    if (!given("--kernel")) r.kernel = c.method.kernel;
    if (!given("--correction")) r.correction = c.method.correction;
    if (!given("--quadrature")) r.quadrature = c.method.quadrature;
    if (!given("--enforcement")) r.contact = c.method.contact;
    // The re-referencing from the file unless given, and apart from it the bound of rebalancing,
    // from the file unless --rebalance-above is given.
    const double rebalance_above = given("--rebalance-above") ? r.rereference.rebalance_above
                                                              : c.rereference.rebalance_above;
    if (!given("--rereference-stretch") && !given("--rereference-every")) r.rereference = c.rereference;
    r.rereference.rebalance_above = rebalance_above;
    if (!given("--mass-scaling-factor") && !given("--mass-scaling-dt")) r.mass_scaling = c.mass_scaling;
  }
  if (r.end_time) {
    c.end_time = *r.end_time;
    c.document["end_time_s"] = *r.end_time;
  }
  r.case_name = c.name;
  // A restart takes the same material as its run: the choice depends on the document alone.
  const bool temperature = case_file::uses_johnson_cook_state(c);  // or damage
  if (c.geometry == geometry::axisymmetric::name)
    return temperature ? run_file_case<geometry::axisymmetric, case_file::material_type>(r, c, restart)
                       : run_file_case<geometry::axisymmetric, case_file::j2_material>(r, c, restart);
  return temperature ? run_file_case<geometry::plane_strain, case_file::material_type>(r, c, restart)
                     : run_file_case<geometry::plane_strain, case_file::j2_material>(r, c, restart);
}

}  // namespace rkpm::runner
