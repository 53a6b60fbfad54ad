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

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

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

}  // namespace

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
