// The whole explicit step on 1, 2 and 3 processes (parallel/distributed_solver.hpp; run by ctest
// as mpi.distributed_step.ranks_N): the copper bar of mpi/bar_impact.hpp (axisymmetric, J2,
// Q2) thrown at 150 m/s onto a rigid anvil with Coulomb friction, so that a step has all of its
// parts: the axis constraints (u_r = 0) and the contact corrections on the shared region, the
// force loop with redundant points, the stable step's power iterations (the first, and again
// as the face is crushed) and every energy sum. Each rank also runs the one-process solver on
// the whole model. After every few steps the ranks' owned coefficients and velocities, gathered
// on rank 0, equal one process's bit for bit (memcmp), and so do the time, the step size, every
// energy of the ledger, the plastic work, the tools' impulse and the largest penetration, on
// every rank. Partitions: METIS's; a cut along the axis at mid-radius (the contact face and every
// constraint's row cross it); and particles dealt by index mod P, where nearly every neighbour is
// another rank's; and the coordinate bisection of the reference positions (straight cuts).

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/coordinate_bisection.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/partition.hpp>

#include "mpi/bar_impact.hpp"

namespace test_mpi_distributed_step {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;

namespace {

using test::bar::solver_type;
using test::bar::impact;
using test::bar::options;
using test::bar::differing;
using test::bar::differing_particles;
using test::bar::same_totals;

void check_partition(communicator& world, const particle_partition& partition, const std::string& name,
                     int steps, int every) {
  CAPTURE(name);
  solver_type one(test::bar::model(), impact(), options());
  distributed_solver<solver_type> part(world, test::bar::model(), impact(), options(), partition);
  for (int n = 1; n <= steps; ++n) {
    one.step();
    part.solver().step();
    if (n % every != 0 && n != steps) continue;
    CAPTURE(n);
    CHECK(same_totals(one, part.solver()));
    const differing_particles differ = differing(world, part, one);
    CHECK(differ.coefficients == 0);
    CHECK(differ.velocities == 0);
  }
  // The run did what the test is for: contact, plastic flow and re-estimated steps.
  CHECK(one.last_contact().active > 0);
  CHECK(one.energy().plastic > 0.0);
  CHECK(one.constraints().size() > 0);
  CHECK(one.min_time_step() < one.max_time_step());
}

}  // namespace

TEST_CASE("the explicit step on 1, 2 or 3 ranks: one process's coefficients, velocities and energies, bit for bit") {
  communicator world;
  const int P = world.size();
  const discrete_model m = test::bar::model();
  check_partition(world, partition_particles(m.at_points, m.particle_count(), P), "METIS", 40, 10);
  std::vector<stored_index> along_axis(m.particle_count()), dealt(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) {
    along_axis[I] = static_cast<stored_index>(
        std::min<double>(P - 1, std::floor(P * m.particles.position[I][0] / (1.0001 * test::bar::radius))));
    dealt[I] = static_cast<stored_index>(I % P);
  }
  check_partition(world, given_partition(along_axis, P), "cut along the axis", 40, 20);
  check_partition(world, given_partition(dealt, P), "dealt by index", 20, 20);
  check_partition(world, bisect_coordinates(m.particles.position, P), "coordinate bisection", 40, 20);
}

}  // namespace test_mpi_distributed_step
