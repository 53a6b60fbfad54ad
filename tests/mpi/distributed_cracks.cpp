// Cracks on 1, 2 and 3 processes (solver/part_cracks.hpp, parallel/distributed_rereference.hpp;
// run by ctest as mpi.distributed_cracks.ranks_N): a brittle bar (material::rankine_fracture)
// whose halves are thrown apart breaks across its middle, its crack grown cell by cell, on P
// ranks against the one-process run every rank also steps (tests/numeric/fracture.cpp's bar, at
// its coarser spacing). Every 20 steps and at the end the ranks' owned coefficients, velocities
// and current positions equal one process's bit for bit, and so do the totals (time, step size,
// every energy, the fracture energy among them) and the cuts (cell, sides, crossings). A
// checkpoint written on P ranks after the first cuts is one process's file byte for byte (so any
// count reads the same state), and read on P ranks, and into one process, it continues to the
// uninterrupted run's bits through the rest of the crack; the end's checkpoint read into one
// process has the same fragments (two pieces). The run stops ten steps after the bar came apart.
// The run's fragments (distributed_solver::fragments) are one process's throughout, and the
// broken bar's model set up again on the ranks on three partitions counts its two pieces as one
// process does (parallel/run_fragments.hpp).
// The parts' decision to cut is the whole model's: as many rebuilds as one process's re-references.
// Contact on the crack faces (all body pairs, docs/method.md (114)): a soft elastic strip cut
// clean through across its middle before the run (cut_cells), its pieces thrown at each other at
// 1 m/s while a lid falls onto its top, 200 steps on P ranks (the pieces meet, rebound at 0.92 m/s
// and part) for METIS's partition and for columns of particles dealt to the ranks in turn (the
// crack a cut too): every 20 steps the owned coefficients and velocities and every total (the
// contact work among them) are one process's bits, and every rank finds each of one process's
// contacts, on the faces and on the surfaces (taken in the whole model's order).

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/material/rankine_fracture.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/distributed_checkpoint.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/gather.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/solver/checkpoint.hpp>
#include <rkpm/solver/config.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "support/bits_and_bytes.hpp"
namespace test_mpi_distributed_cracks {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;

namespace {

using rkpm::test::file_bytes;
using rkpm::test::same_bits;

using brittle = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::plane_strain,
                       material::rankine_fracture, contact::none>;
using solver_type = solver_for<brittle>;
constexpr std::string_view configuration = "brittle bar thrown apart";

// PMMA-like, Poisson's ratio 0; the halves' speed V makes rho c V exceed sigma_t at the middle.
constexpr double E = 3e9, rho = 1180.0, sigma_t = 10e6, G_c = 500.0, L = 20e-3, H = 4e-3, V = 10.0, h = 0.5e-3;

problem_for<brittle> bar() {
  const Eigen::Vector2i n(static_cast<int>(std::lround(L / h)) + 1, static_cast<int>(std::lround(H / h)) + 1);
  problem_for<brittle> p{
      .particles = make_grid_particles<2>(vec2(0.0, 0.0), vec2(L, H), n, 2.0),
      .mesh = make_grid_mesh(vec2(0.0, 0.0), vec2(L, H), n),
      .material = material::rankine_fracture(
          {E, 0.0, rho}, sigma_t, G_c, material::rankine_fracture::band_width_of_support<kernel::cubic_spline>(2.0 * h)),
      .contact = {}};
  // Faster at the top: the crack starts there and runs down across the bar, cell by cell.
  p.initial_particle_velocity = [](index_t, const vec2& X) {
    return vec2((X[0] <= 0.5 * L + 1e-9 ? -V : V) * 2.0 * X[1] / H, 0.0);
  };
  return p;
}

run_options options() {
  run_options o;
  o.end_time = 3.0 * L / std::sqrt(E / rho);
  return o;
}

distributed_solver<solver_type> on_ranks(communicator& world) {
  const discrete_model whole = make_solver<brittle>(bar(), options()).model();
  distributed_solver<solver_type> run(world, whole, bar(), options(),
                                      partition_particles(whole.at_points, whole.particle_count(), world.size()));
  run.rereference_through([] { return make_solver<brittle>(bar(), options()); });
  return run;
}

std::vector<double> totals(const solver_type& s) {
  const energy_balance& e = s.energy();
  return {s.time(), s.time_step(), e.kinetic, e.internal, e.external, e.constraint, e.plastic, e.remap, s.min_stretch()};
}

bool same_cuts(const std::vector<cell_crack>& a, const std::vector<cell_crack>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k].cell != b[k].cell || a[k].side != b[k].side || std::memcmp(a[k].at.data(), b[k].at.data(), 2 * sizeof(double)) != 0)
      return false;
  return true;
}

// Whether the ranks' owned values, the totals and the cuts are one process's bits (collective).
void same_run(communicator& world, const distributed_solver<solver_type>& run, const solver_type& one) {
  const solver_type& s = run.solver();
  const std::vector<vec2> d = gather_owned(world, run.plan(), s.coefficients()),
                          v = gather_owned(world, run.plan(), s.coefficient_velocities()),
                          x = gather_owned(world, run.plan(), s.particle_positions());
  if (world.rank() == 0) {
    CHECK(same_bits(d, one.coefficients()));
    CHECK(same_bits(v, one.coefficient_velocities()));
    CHECK(same_bits(x, one.particle_positions()));
  }
  CHECK(same_bits(totals(s), totals(one)));
  CHECK(same_cuts(s.cracks(), one.cracks()));
  CHECK(s.rereference_times() == one.rereference_times());
  // The run's pieces (parallel/run_fragments.hpp at the set-up, the whole solver's at a rebuild).
  CHECK(run.fragments().pieces == one.fragments().pieces);
  CHECK(same_bits(std::vector<double>{run.fragments().largest_mass, s.fragments().largest_mass},
                  std::vector<double>{one.fragments().largest_mass, one.fragments().largest_mass}));
}

// The pieces of `model` counted over the ranks on `partition` (a distributed solver's set-up:
// parallel/run_fragments.hpp) equal one process's, the largest piece's mass to the bit (collective).
void same_pieces(communicator& world, const discrete_model& model, const particle_partition& partition,
                 const std::string& name) {
  CAPTURE(name);
  const solver_type one(model, bar(), options());
  const distributed_solver<solver_type> run(world, model, bar(), options(), partition);
  CHECK(one.fragments().pieces == 2);
  CHECK(run.fragments().pieces == one.fragments().pieces);
  CHECK(same_bits(std::vector<double>{run.fragments().largest_mass},
                  std::vector<double>{one.fragments().largest_mass}));
}

// ---- The cut strip: a soft elastic strip (plane strain, effective-mass contact without friction:
// tests/numeric/self_contact.cpp's cut bar, shorter and taller), cut across the cells between
// particle columns 10 and 11 before the run, its pieces thrown at each other; a lid of the same
// stuff 20 um above it falls onto its top. All body pairs: the crack's faces, and the surfaces.
using cut_config = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                          material::elastic,
                          contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::frictionless>>;
using cut_solver = solver_for<cut_config>;  // compiled once (solver/solver_instances.hpp)
constexpr int cut_nx = 22, cut_ny = 11, lid_nx = 8, lid_ny = 4, cut_column = 10;
constexpr double cut_h = 1e-3, cut_E = 1e7, cut_rho = 1000.0, cut_speed = 1.0, lid_gap = 2e-5;
constexpr double cut_x = (cut_column + 0.5) * cut_h;  // the crack's x, and each piece's length
constexpr double strip_top = (cut_ny - 1) * cut_h;

problem_for<cut_config> cut_bar_problem() {
  const double length = (cut_nx - 1) * cut_h, lid_bottom = strip_top + lid_gap;
  problem_for<cut_config> p{
      .particles = make_grid_particles<2>(vec2(0.0, 0.0), vec2(length, strip_top), Eigen::Vector2i(cut_nx, cut_ny), 2.0),
      .mesh = make_grid_mesh(vec2(0.0, 0.0), vec2(length, strip_top), Eigen::Vector2i(cut_nx, cut_ny)),
      .material = material::elastic({cut_E, 0.0, cut_rho}),
      .contact = typename cut_config::contact_type({}, contact::all_body_pairs),
      .initial_velocity = [](const vec2& X) {
        if (X[1] > strip_top) return vec2(0.0, -cut_speed);
        return vec2(X[0] < cut_x ? cut_speed : -cut_speed, 0.0);
      }};
  const vec2 lo(0.0, lid_bottom), hi((lid_nx - 1) * cut_h, lid_bottom + (lid_ny - 1) * cut_h);
  append_body(p.particles, p.mesh, make_grid_particles<2>(lo, hi, Eigen::Vector2i(lid_nx, lid_ny), 2.0),
              make_grid_mesh(lo, hi, Eigen::Vector2i(lid_nx, lid_ny)));
  return p;
}

run_options cut_bar_options() {
  run_options o;
  o.end_time = 1.0;  // stepped by hand
  return o;
}

// The strip's model with the crack through its column of cells, as one process cuts it.
discrete_model cut_bar_model() {
  cut_solver s = make_solver<cut_config>(cut_bar_problem(), cut_bar_options());
  std::vector<std::pair<index_t, vec2>> column;
  for (index_t row = 0; row + 1 < cut_ny; ++row) column.emplace_back(row * (cut_nx - 1) + cut_column, vec2(1.0, 0.0));
  s.cut_cells(column);
  return s.model();
}

// The solver's contacts in its last step: on the crack's faces (a face point the slave or the
// master), and between particles and surfaces.
std::array<index_t, 2> contacts(const cut_solver& s) {
  std::array<index_t, 2> n{};
  for (const auto& c : s.contact().bodies().active_pairs())
    ++n[c.slave >= s.model().particle_count() || c.a >= s.model().particle_count() ? 0 : 1];
  return n;
}

std::vector<double> cut_totals(const cut_solver& s) {
  const energy_balance& e = s.energy();
  return {s.time(), s.time_step(), e.kinetic, e.internal, e.external, e.contact, s.max_penetration()};
}

// The left piece's mean velocity along the strip.
double left_velocity(const cut_solver& s) {
  double p = 0.0, m = 0.0;
  for (index_t I = 0; I < cut_nx * cut_ny; ++I)
    if (I % cut_nx <= cut_column) {
      p += s.mass()[I] * s.coefficient_velocities()[I][0];
      m += s.mass()[I];
    }
  return p / m;
}

// 200 steps of the strip on `partition` against one process (collective).
void contact_on_faces(communicator& world, const discrete_model& model, const particle_partition& partition,
                      const std::string& name) {
  CAPTURE(name);
  cut_solver one(model, cut_bar_problem(), cut_bar_options());
  distributed_solver<cut_solver> run(world, model, cut_bar_problem(), cut_bar_options(), partition);
  const double K0 = one.kinetic_energy();
  std::array<index_t, 2> one_contacts{}, part_contacts{};
  index_t differing = 0;
  for (int n = 1; n <= 200; ++n) {
    one.step();
    run.step();
    for (int k = 0; k < 2; ++k) {
      one_contacts[k] += contacts(one)[k];
      part_contacts[k] += contacts(run.solver())[k];
    }
    if (n % 20 == 0) {
      const std::vector<vec2> d = gather_owned(world, run.plan(), run.solver().coefficients()),
                              v = gather_owned(world, run.plan(), run.solver().coefficient_velocities());
      if (world.rank() == 0)
        differing += !same_bits(d, one.coefficients()) + !same_bits(v, one.coefficient_velocities());
      differing += !same_bits(cut_totals(run.solver()), cut_totals(one));
    }
  }
  MESSAGE(name << ": " << one_contacts[0] << " contacts on the faces and " << one_contacts[1]
               << " on the surfaces in 200 steps (t = " << one.time() << " s), contact work "
               << one.energy().contact / K0 << " K0, the left piece at " << left_velocity(one) << " m/s, "
               << run.shared_count() << " particles shared");
  CHECK(differing == 0);
  CHECK(part_contacts == one_contacts);  // every rank corrects every contact, as one process does
  // What the test is for: the faces touch and their contact acts; the pieces rebound; the lid
  // hits the strip (contacts of surface slaves, taken in the whole model's order on every rank).
  CHECK(one_contacts[0] > 0);
  CHECK(one_contacts[1] > 0);
  CHECK(one.energy().contact < -0.01 * K0);
  CHECK(left_velocity(one) < -0.9 * cut_speed);
}

}  // namespace

TEST_CASE("contact on crack faces on P ranks: one process's bits, each contact on the faces found on every rank") {
  communicator world;
  const discrete_model model = cut_bar_model();
  REQUIRE(model.crack_faces.faces() == 2 * (cut_ny - 1));
  std::vector<stored_index> columns(model.particle_count());
  for (index_t I = 0; I < model.particle_count(); ++I) columns[I] = static_cast<stored_index>(I % cut_nx % world.size());
  contact_on_faces(world, model, partition_particles(model.at_points, model.particle_count(), world.size()), "METIS");
  contact_on_faces(world, model, given_partition(columns, world.size()), "columns dealt");
}

TEST_CASE("a crack grown on P ranks is one process's, bit for bit, and restarts from its checkpoint on any count") {
  communicator world;
  // One folder per process count: ctest runs ranks_1, _2 and _3 side by side, each removing its own.
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / fmt::format("rkpm_test_distributed_cracks_{}", world.size());
  if (world.rank() == 0) std::filesystem::create_directories(folder);
  MPI_Barrier(world.get());
  const std::filesystem::path from_ranks = folder / fmt::format("ranks_{}.rkpm", world.size()),
                              from_one = folder / fmt::format("one_{}_{}.rkpm", world.size(), world.rank());
  solver_type one = make_solver<brittle>(bar(), options());
  distributed_solver<solver_type> run = on_ranks(world);
  std::optional<distributed_solver<solver_type>> again;  // read from the ranks' checkpoint, on the ranks
  std::optional<solver_type> again_one;                  // and on one process
  index_t cuts_at_checkpoint = 0;
  int broken_for = 0;  // steps since the bar came apart: ten more, then the run stops
  for (int n = 1; one.before_end() && broken_for < 10; ++n) {
    one.step_to_end();
    run.step_to_end();
    if (again) again->step_to_end();
    if (again_one) again_one->step_to_end();
    if (!again && one.cracks().size() >= 2) {
      cuts_at_checkpoint = static_cast<index_t>(one.cracks().size());
      write_checkpoint(run, from_ranks, configuration);
      rkpm::write_checkpoint(one, from_one, configuration);
      CHECK(file_bytes(from_ranks) == file_bytes(from_one));
      again.emplace(on_ranks(world));
      read_checkpoint(*again, from_ranks, configuration);
      if (world.rank() == 0) {
        again_one.emplace(make_solver<brittle>(bar(), options()));
        rkpm::read_checkpoint(*again_one, from_ranks, configuration);
      }
    }
    if (one.fragments().pieces == 2) ++broken_for;
    if (n % 20 == 0) {
      CAPTURE(n);
      same_run(world, run, one);
    }
  }
  MESSAGE(one.steps() << " steps, " << cuts_at_checkpoint << " cuts at the checkpoint, " << one.cracks().size()
                      << " at the end, " << one.rereferences() << " rebuilds of one process, " << run.rebuilds()
                      << " on the ranks");
  same_run(world, run, one);
  REQUIRE(again);
  same_run(world, *again, one);
  if (world.rank() == 0) {
    REQUIRE(again_one);
    CHECK(same_bits(again_one->coefficients(), one.coefficients()));
    CHECK(same_bits(totals(*again_one), totals(one)));
    CHECK(same_cuts(again_one->cracks(), one.cracks()));
  }
  // What the test is for: a crack grown through several cells, across the ranks, after the restart too.
  CHECK(cuts_at_checkpoint >= 2);
  CHECK(static_cast<index_t>(one.cracks().size()) >= cuts_at_checkpoint + 3);
  CHECK(one.fragments().pieces == 2);
  CHECK(one.energy().plastic > 0.5 * G_c * H);
  // The parts decide as the whole model does (solver/part_cracks.hpp): no rebuild that cuts nothing.
  CHECK(run.rebuilds() == one.rereferences());

  // The end's state from the ranks, read into one process: the same file, the same pieces.
  write_checkpoint(run, from_ranks, configuration);
  rkpm::write_checkpoint(one, from_one, configuration);
  CHECK(file_bytes(from_ranks) == file_bytes(from_one));
  if (world.rank() == 0) {
    solver_type mirror = make_solver<brittle>(bar(), options());
    rkpm::read_checkpoint(mirror, from_ranks, configuration);
    CHECK(mirror.fragments().pieces == one.fragments().pieces);
    CHECK(mirror.fragments().largest_mass == one.fragments().largest_mass);
  }
  // The broken bar's model set up on the ranks: its two pieces counted over the ranks, on METIS's
  // partition, on columns of particles dealt to the ranks in turn (every column a cut, so a label
  // crosses cuts over several rounds) and on the columns dealt from the right.
  const discrete_model& broken = one.model();
  std::vector<stored_index> columns(broken.particle_count()), from_right(broken.particle_count());
  for (index_t I = 0; I < broken.particle_count(); ++I) {
    const auto column = static_cast<index_t>(std::lround(broken.particles.position[I][0] / h));
    columns[I] = static_cast<stored_index>(column % world.size());
    from_right[I] = static_cast<stored_index>((std::lround(L / h) - column) % world.size());
  }
  same_pieces(world, broken, partition_particles(broken.at_points, broken.particle_count(), world.size()), "METIS");
  same_pieces(world, broken, given_partition(columns, world.size()), "columns dealt");
  same_pieces(world, broken, given_partition(from_right, world.size()), "columns dealt from the right");
  std::filesystem::remove(from_one);
  MPI_Barrier(world.get());
  if (world.rank() == 0) std::filesystem::remove_all(folder);
}

}  // namespace test_mpi_distributed_cracks
