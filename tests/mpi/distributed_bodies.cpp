// Contact between deformable bodies on 1, 2 and 3 processes (parallel/distributed_solver.hpp; run
// by ctest as mpi.distributed_bodies.ranks_N): cases/rod_on_rod.hpp at a small size (two copper
// rods of 5 x 17 particles meeting head on at 2 x 227 m/s, each slave against the other, with
// Coulomb friction 0.2). The bodies' surfaces and their rows are held by every rank (the shared
// region), which corrects both sides of every contact as one process does. After 30 steps the
// owned coefficients and velocities gathered on rank 0, and every total (time, step size,
// energies, plastic work, penetration), equal one process's bit for bit, for METIS's partition,
// the rods on different ranks (the contact plane is the cut) and particles dealt by index.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/solver/make_solver.hpp>

#include "cases/rod_on_rod.hpp"
#include "mpi/bar_impact.hpp"

namespace test_mpi_distributed_bodies {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;
using test::bar::solver_type;  // axisymmetric, J2, particle_to_segment<paper, coulomb>: rod_on_rod's too
using rods = cases::rod_on_rod;

namespace {

rods::parameters small_rods() {
  rods::parameters p;
  p.radial_particles = 5;
  p.axial_particles = 17;
  p.friction = 0.2;
  return p;
}

problem<test::bar::material_type, test::bar::contact_type> rods_problem() {
  return rods::build<test::bar::contact_type>(small_rods(), 1);
}

discrete_model rods_model() {
  const auto p = rods_problem();
  return build_discrete_model<kernel::cubic_spline, correction::linear, quadrature::q2, rods::geometry_type>(
      p.particles, p.mesh);
}

run_options rods_options() {
  run_options o;
  o.end_time = 1.0;  // stepped by hand
  return o;
}

void check_partition(communicator& world, const particle_partition& partition, const std::string& name) {
  CAPTURE(name);
  solver_type one(rods_model(), rods_problem(), rods_options());
  distributed_solver<solver_type> part(world, rods_model(), rods_problem(), rods_options(), partition);
  index_t most_contacts = 0;
  for (int n = 0; n < 30; ++n) {
    one.step();
    part.solver().step();
    most_contacts = std::max(most_contacts, one.last_contact().active);
  }
  CHECK(test::bar::same_totals(one, part.solver()));
  const test::bar::differing_particles n = test::bar::differing(world, part, one);
  CHECK(n.coefficients == 0);
  CHECK(n.velocities == 0);
  // The rods did meet: contacts between them, and plastic flow.
  CHECK(most_contacts > 0);
  CHECK(one.energy().plastic > 0.0);
}

}  // namespace

TEST_CASE("contact between deformable bodies on 1, 2 or 3 ranks: one process's results, bit for bit") {
  communicator world;
  const int P = world.size();
  const discrete_model m = rods_model();
  REQUIRE(m.bodies.count() == 2);
  check_partition(world, partition_particles(m.at_points, m.particle_count(), P), "METIS");
  std::vector<stored_index> by_rod(m.particle_count()), dealt(m.particle_count());
  for (index_t I = 0; I < m.particle_count(); ++I) {
    // The lower rod on rank 0, the upper one on the others (split along z).
    const vec2& X = m.particles.position[I];
    by_rod[I] = m.bodies.of_particle(I) == 0 || P == 1
                    ? 0
                    : static_cast<stored_index>(1 + std::min<double>(P - 2, std::floor((P - 1) * X[1] / 32.4e-3)));
    dealt[I] = static_cast<stored_index>(I % P);
  }
  check_partition(world, given_partition(by_rod, P), "a rod per rank");
  check_partition(world, given_partition(dealt, P), "dealt by index");
}

}  // namespace test_mpi_distributed_bodies
