// Tutorial 11: one run on several processes, with the same bits as on one.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// The Taylor bar of tutorial 04 (cases/taylor_bar.hpp), refined: resolution 8 puts 64,561
// particles and 129,024 Q2 points in the half section. This program runs it on the processes
// mpiexec starts, each owning a part of the particles (docs/method.md section 9.8):
//
//   mpiexec -np 3 build/tutorials/tutorial_11_many_processes [output directory] [end time s] [resolution]
//   (defaults: results/11_many_processes, 2e-6 s, resolution 8; one thread per process:
//    OMP_NUM_THREADS=1)
//
// What it shows:
//   1. The partition: METIS cuts the particles' graph (two particles are linked when a quadrature
//      point's support holds both) into as many parts as processes; partition_P.png draws the
//      half section coloured by owner.
//   2. The run: parallel::distributed_solver builds each rank's part of the model and steps it.
//      Owned particles are updated by their owner, ghost copies forwarded after each update,
//      every sum taken in one process's order.
//   3. The result: rank 0 gathers the owned coefficients and prints the bar's radius and height
//      in mm, the energies, and a CRC-32 of the coefficients' and velocities' bytes. Run it on 1,
//      2 and 3 processes: the lines are the same, to the last bit.
//   4. The snapshot: each rank writes its piece of bar_end.pvtu (the .vtu of its particles and
//      cells) at the same time as the others, and rank 0 the index that ParaView opens.
//   5. The time per step, for the README's table (tools/rkpm bench --halo measures the ratios
//      properly, round by round).

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/io/crc32.hpp>
#include <rkpm/io/field_figure.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/gather.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/parallel/snapshot_pieces.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/taylor_bar.hpp"

namespace fs = std::filesystem;
using namespace rkpm;
using taylor_bar = cases::taylor_bar;

// ---------------------------------------------------------------------------------------
// The method, as in tutorial 04, with the paper's two-point rule
// ---------------------------------------------------------------------------------------
using contact_t = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using method = config<kernel::cubic_spline, correction::linear, quadrature::q2, taylor_bar::geometry_type,
                      taylor_bar::material_type, contact_t>;
using solver_type = solver_for<method>;

int main(int argc, char** argv) {
  // MPI lives as long as the session; an exception that escapes a rank's work ends every rank.
  parallel::mpi_session session(argc, argv);
  parallel::communicator world;
  const bool root = world.rank() == 0;
  const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path("results/11_many_processes");
  const double end_time = argc > 2 ? std::atof(argv[2]) : 2e-6;
  const int resolution = argc > 3 ? std::atoi(argv[3]) : 8;
  try {
    if (root) fs::create_directories(dir);

    // ---------------------------------------------------------------------------------------
    // 1. The whole model, on every rank, and its partition
    // ---------------------------------------------------------------------------------------
    // Every rank builds the same model from the same problem (the set-up is not divided yet);
    // METIS's partition is deterministic, so every rank finds the same parts.
    const taylor_bar::parameters params{};
    auto problem = taylor_bar::build<contact_t>(params, resolution);
    run_options options;
    options.end_time = end_time;
    discrete_model whole = build_discrete_model<kernel::cubic_spline, correction::linear, quadrature::q2,
                                                taylor_bar::geometry_type>(problem.particles, problem.mesh,
                                                                           options.max_moment_condition);
    // The impact face's particles (z = 0 in the reference configuration), whose largest radius
    // cases/taylor_bar.hpp measures.
    std::vector<char> on_face(whole.particle_count());
    for (index_t I = 0; I < whole.particle_count(); ++I) on_face[I] = whole.particles.position[I][1] <= 1e-12;
    const parallel::particle_partition partition =
        parallel::partition_particles(whole.at_points, whole.particle_count(), world.size());
    if (root) {
      std::vector<double> owner(partition.part.begin(), partition.part.end());
      io::field_png(dir / fmt::format("partition_{}.png", world.size()), whole.particles.position,
                    io::vertex_cells(whole.particles.position.size()), owner, {},
                    {.title = fmt::format("Taylor bar, resolution {}: {} particles on {} processes", resolution,
                                          whole.particle_count(), world.size()),
                     .label = "process"});
      fmt::print("{} particles, {} points, on {} processes\n", whole.particle_count(), whole.point_count(),
                 world.size());
    }

    // ---------------------------------------------------------------------------------------
    // 2. Each rank's part, and the run
    // ---------------------------------------------------------------------------------------
    const auto start = std::chrono::steady_clock::now();
    // Which cells of the snapshot each rank writes, from the whole model's cells (before the
    // whole model is handed to the run and let go).
    parallel::snapshot_pieces pieces(world, partition, io::snapshot_cells(whole));
    parallel::distributed_solver<solver_type> run(world, std::move(whole), std::move(problem), options, partition);
    const auto stepping = std::chrono::steady_clock::now();
    solver_type& s = run.solver();
    if (root)
      fmt::print("rank 0 owns {} particles and holds {} ghosts; every rank holds the {} particles of the contact "
                 "face, the axis and their neighbours ({:.1f}%); first step {:.4g} ns\n",
                 run.plan().owned.size(), run.plan().ghosts.size(), run.shared_count(),
                 100.0 * run.shared_count() / static_cast<double>(run.plan().global_particles),
                 s.time_step() * 1e9);
    double next_report = 0.1 * end_time;
    s.run([&](const solver_type& at) {
      if (root && at.time() >= next_report) {
        fmt::print("  t = {:7.3f} us, step {}\n", at.time() * 1e6, at.steps());
        next_report += 0.1 * end_time;
      }
    }, 1);
    const double step_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - stepping).count();
    const double setup_s = std::chrono::duration<double>(stepping - start).count();

    // ---------------------------------------------------------------------------------------
    // 4. The snapshot, in pieces
    // ---------------------------------------------------------------------------------------
    // Every rank writes bar_end_<rank>.vtu: its particles and its cells, with displacement,
    // velocity, stress, plastic strain, det F and each point's index in the whole model; rank 0
    // then writes bar_end.pvtu, which names them.
    pieces.write(s, dir / "bar_end.pvtu");

    // ---------------------------------------------------------------------------------------
    // 3. What one process would print
    // ---------------------------------------------------------------------------------------
    // Physical positions x = X + sum_J N_J(X) d_J: each owner computes its particles' (their
    // rows' columns are among its particles and ghosts), rank 0 gathers them in global order.
    const std::vector<vec2> x = parallel::gather_owned(world, run.plan(), s.particle_positions());
    const std::vector<vec2> d = parallel::gather_owned(world, run.plan(), s.coefficients());
    const std::vector<vec2> v = parallel::gather_owned(world, run.plan(), s.coefficient_velocities());
    if (root) {
      double radius = 0.0, height = 0.0;
      for (const vec2& at : x) height = std::max(height, at[1]);
      for (std::size_t I = 0; I < x.size(); ++I)
        if (on_face[I]) radius = std::max(radius, x[I][0]);
      std::uint32_t crc = io::crc32_of(reinterpret_cast<const char*>(d.data()), d.size() * sizeof(vec2));
      crc = io::crc32_of(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(vec2), crc);
      const energy_balance& e = s.energy();
      fmt::print("t = {:.6g} s after {} steps: radius {:.17g} mm, height {:.17g} mm\n", s.time(), s.steps(),
                 radius * 1e3, height * 1e3);
      fmt::print("energies (J): kinetic {:.17g}, internal {:.17g}, plastic {:.17g}, contact {:.17g}\n", e.kinetic,
                 e.internal, e.plastic, e.contact);
      fmt::print("CRC-32 of the coefficients and velocities: {:08x}\n", crc);
      fmt::print("set-up {:.2f} s, {:.3f} ms per step on {} processes\n", setup_s, 1e3 * step_s / s.steps(),
                 world.size());
    }
  } catch (const parallel::rank_failure& e) {  // agreed by every rank: one line, a clean stop
    if (root) std::fprintf(stderr, "tutorial_11_many_processes: %s\n", e.what());
    return 1;
  }
  return 0;
}
