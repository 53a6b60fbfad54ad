// The whole explicit step on 1, 2 and 3 processes (parallel/distributed_solver.hpp; run by ctest
// as mpi.distributed_step.ranks_N): the copper bar of mpi/bar_problem.hpp (axisymmetric, J2,
// Q2) thrown at 150 m/s onto a rigid anvil with Coulomb friction, so that a step has all of its
// parts: the axis constraints (u_r = 0) and the contact corrections on the shared region, the
// force loop with redundant points, the stable step's power iterations (the first, and again
// as the face is crushed) and every energy sum. Each rank also runs the one-process solver on
// the whole model. After every few steps the ranks' owned coefficients and velocities, gathered
// on rank 0, equal one process's bit for bit (memcmp), and so do the time, the step size, every
// energy of the ledger, the plastic work, the tools' impulse and the largest penetration, on
// every rank. Partitions: METIS's; a cut along the axis at mid-radius (the contact face and every
// constraint's row cross it); and particles dealt by index mod P, where nearly every neighbour is
// another rank's.

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/distributed_solver.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/solver/explicit_solver.hpp>

#include "mpi/bar_problem.hpp"
#include "mpi/gather_owned.hpp"

namespace test_mpi_distributed_step {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;
using namespace rkpm::parallel;

namespace {

using G = test::bar::geometry_type;
using M = test::bar::material_type;
using Ct = contact::particle_to_segment<contact::enforcement::paper, contact::friction::coulomb>;
using solver_type = explicit_solver<G, M, Ct>;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

problem<M, Ct> impact() {
  // The anvil 20 um below the bar's face: the first steps fly, then the face is crushed.
  const contact::rigid_tool anvil("anvil", {vec2(-1e-3, -2e-5), vec2(2 * test::bar::radius, -2e-5)},
                                  contact::side::left, contact::tool_motion::fixed());
  return {.particles = {},
          .mesh = {},
          .material = test::bar::copper(),
          .contact = Ct({anvil}, contact::friction::coulomb{0.2}),
          .initial_velocity = [](const vec2&) { return vec2(0.0, -150.0); }};
}

run_options options() {
  run_options o;
  o.end_time = 1.0;  // stepped by hand
  o.time_step_update_interval = 3;
  return o;
}

// What every rank compares: the totals, the same on every rank.
std::vector<double> totals(const solver_type& s) {
  const energy_balance& e = s.energy();
  return {s.time(), s.time_step(), e.kinetic, e.internal, e.external, e.contact, e.constraint, e.plastic,
          s.tool_impulses()[0][0], s.tool_impulses()[0][1], s.max_penetration(), s.min_stretch()};
}

struct gathered {
  std::vector<vec2> d, v;
};

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
    const std::vector<double> a = totals(one), b = totals(part.solver());
    index_t differ = 0;
    for (std::size_t k = 0; k < a.size(); ++k) differ += !same_bits(a[k], b[k]);
    CHECK(differ == 0);
    const gathered g{test::gather_owned(world, part.plan(), part.solver().coefficients()),
                     test::gather_owned(world, part.plan(), part.solver().coefficient_velocities())};
    if (world.rank() == 0) {
      index_t d_differ = 0, v_differ = 0;
      for (index_t I = 0; I < one.model().particle_count(); ++I) {
        d_differ += std::memcmp(g.d[I].data(), one.coefficients()[I].data(), sizeof(vec2)) != 0;
        v_differ += std::memcmp(g.v[I].data(), one.coefficient_velocities()[I].data(), sizeof(vec2)) != 0;
      }
      CHECK(d_differ == 0);
      CHECK(v_differ == 0);
    }
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
}

}  // namespace test_mpi_distributed_step
