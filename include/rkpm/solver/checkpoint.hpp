#pragma once
// Exact restart (docs/method.md section 9.5): write_checkpoint stores a solver's whole state
// between steps; read_checkpoint puts it into a solver built from the same problem and
// configuration, which then continues bit for bit as the writer would have (at one thread;
// with more, runs themselves agree only to round-off).
// The format and its checks are io/checkpoint_format.hpp's and io/checkpoint_reader.hpp's; here the solver is identified: the
// configuration name the caller passes (Config::name()), the particle, quadrature-point, slave
// and tool counts, and the lumped masses, which differ for another geometry, density or
// particle placement with the same counts.
//
//   rkpm::write_checkpoint(solver, out / rkpm::io::checkpoint_file_name(solver.steps()), Config::name());
//   auto again = rkpm::make_solver<Config>(problem, options);
//   rkpm::read_checkpoint(again, path, Config::name());

#include <filesystem>
#include <numeric>
#include <ranges>
#include <string>
#include <string_view>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/io/checkpoint.hpp>
#include <rkpm/io/checkpoint_parts.hpp>
#include <rkpm/solver/explicit_solver.hpp>

namespace rkpm {

// The solver's sections of per-particle and per-point arrays (solver/explicit_solver.hpp,
// solver/time_step_controller.hpp, solver/point_materials.hpp, write_checkpoint below): on several
// processes, a rank holds its part of them (parallel/distributed_checkpoint.hpp,
// io/checkpoint_parts.hpp); every other section is the same on every rank.
// The reference's arrays are empty until a re-reference (and a nodal rule's carried points always):
// an empty array is written and read as it is, the same on every rank.
inline constexpr std::string_view checkpoint_particle_sections[] = {
    "solver.mass",        "solver.d",           "solver.v",          "solver.a",         "solver.f_int",
    "solver.v_half_prev", "clock.mode",         "reference.initial_position", "reference.position",
    "reference.support",  "reference.volume"};
inline constexpr std::string_view checkpoint_point_sections[] = {
    "points.state", "points.tau", "points.F", "points.reference_F", "points.initial_volume_per_weight",
    "reference.point_position", "reference.point_weight"};

template <Geometry G, Material M, Contact Ct>
io::checkpoint_identity checkpoint_identity_of(const explicit_solver<G, M, Ct>& s, std::string_view configuration) {
  return {std::string(configuration), s.model().particle_count(), s.model().point_count(),
          static_cast<index_t>(s.slave_particles().size()), static_cast<index_t>(std::ranges::size(s.contact().tools()))};
}

// Writes through a temporary file and a rename: a run killed meanwhile leaves `path` as it was.
// `description` is free text kept in the header (io::read_checkpoint_header), e.g. the case and
// parameters a restart needs to build the same problem again.
template <Geometry G, Material M, Contact Ct>
void write_checkpoint(const explicit_solver<G, M, Ct>& s, const std::filesystem::path& path,
                      std::string_view configuration, std::string_view description = {}) {
  io::checkpoint_writer w(path, checkpoint_identity_of(s, configuration), description);
  w.array("solver.mass", s.mass());
  w.part(s);
  w.commit();
}

// Refuses, with a one-line rkpm::error, a file that is not a checkpoint of this solver's build,
// configuration and problem, or is truncated or damaged (io::checkpoint_damaged, naming the
// part whose checksum fails); the solver is unchanged when it is refused for any of these
// reasons (a section of another build's layout is found only while loading).
// The solver's sections from a reader whose identity is checked (a file, or bytes held in
// memory: parallel::mirror_state; on a rank of several, through the reader's layout): the lumped
// masses first, which must be this problem's, then the state, then the check that nothing is left.
template <class Solver>
void load_checkpoint(Solver& s, io::checkpoint_reader& r) {
  std::vector<double> mass(s.mass().size());
  r.array("solver.mass", mass);
  if (mass != s.mass())
    fail("checkpoint '{}' is of another problem: its particle masses differ from this one's (another geometry, "
         "density or particle placement)",
         r.file());
  r.part(s);
  r.finish();
}

// A checkpoint in parts (a folder, io/checkpoint_parts.hpp), written on any number of processes,
// into a one-process solver: every part is read in turn, none is held whole with another.
template <Geometry G, Material M, Contact Ct>
void read_checkpoint_parts(explicit_solver<G, M, Ct>& s, const std::filesystem::path& folder,
                           std::string_view configuration) {
  std::vector<stored_index> particles(static_cast<std::size_t>(s.model().particle_count())),
      points(static_cast<std::size_t>(s.model().point_count()));
  std::iota(particles.begin(), particles.end(), stored_index{0});
  std::iota(points.begin(), points.end(), stored_index{0});
  io::checkpoint_parts parts(folder, checkpoint_identity_of(s, configuration),
                             {checkpoint_particle_sections, {}, std::move(particles)},
                             {checkpoint_point_sections, {}, std::move(points)});
  load_checkpoint(s, parts.reader());
}

// A checkpoint file, or a folder of parts (read_checkpoint_parts).
template <Geometry G, Material M, Contact Ct>
void read_checkpoint(explicit_solver<G, M, Ct>& s, const std::filesystem::path& path, std::string_view configuration) {
  if (std::filesystem::is_directory(path)) return read_checkpoint_parts(s, path, configuration);
  io::checkpoint_reader r(path, checkpoint_identity_of(s, configuration));
  load_checkpoint(s, r);
}

}  // namespace rkpm
