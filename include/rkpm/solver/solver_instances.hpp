#pragma once
// explicit_solver for the configurations the project's tests use in several files, compiled once
// instead of once per file (as discretization/shape_table_instances.hpp does for the shape
// tables). The solver's set-up and step are most of a test file's compile time, and about half
// of the tests' solver types are used by two to eight files. A program that wants them once:
//   - compiles the files that define RKPM_INSTANTIATE_SOLVERS to a part number (1 or 2) and
//     include this header (the explicit instantiation definitions of that part), e.g. the
//     project's tests/solver_instances_<part>.cpp;
//   - defines RKPM_EXTERN_SOLVERS in every other file (then explicit_solver.hpp includes this
//     header and declares them extern, so those files only call their set-up and step).
// Without either macro nothing changes: the header-only library instantiates as usual. A
// configuration missing from the list is instantiated where it is used, as before.

#include <rkpm/contact/none.hpp>
#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/solver/explicit_solver.hpp>

// RKPM_SOLVER_PART(n): whether part n is compiled here (every part is declared extern).
#if defined(RKPM_INSTANTIATE_SOLVERS)
#define RKPM_SOLVER_INSTANCE(G, M, C) template class explicit_solver<G, M, C>;
#define RKPM_SOLVER_PART(n) (RKPM_INSTANTIATE_SOLVERS == n)
#elif defined(RKPM_EXTERN_SOLVERS)
#define RKPM_SOLVER_INSTANCE(G, M, C) extern template class explicit_solver<G, M, C>;
#define RKPM_SOLVER_PART(n) 1
#endif

#ifdef RKPM_SOLVER_INSTANCE
namespace rkpm::solver_instances {
namespace e = contact::enforcement;
namespace f = contact::friction;
using plane = geometry::plane_strain;
using axi = geometry::axisymmetric;
using elastic = material::elastic;
using j2_linear = material::j2_plasticity<material::hardening::linear>;
using none = contact::none;
using paper_coulomb = contact::particle_to_segment<e::paper, f::coulomb>;
using paper_frictionless = contact::particle_to_segment<e::paper, f::frictionless>;
using effective_coulomb = contact::particle_to_segment<e::effective_mass, f::coulomb>;
using effective_frictionless = contact::particle_to_segment<e::effective_mass, f::frictionless>;
using penalty_coulomb = contact::particle_to_segment<e::penalty, f::coulomb>;
}  // namespace rkpm::solver_instances

namespace rkpm {
// In two parts of about equal compile time, built side by side (each file compiled costs
// seconds of its own before its instantiations: more parts would not pay on two cores).
#if RKPM_SOLVER_PART(1)
RKPM_SOLVER_INSTANCE(solver_instances::plane, solver_instances::elastic, solver_instances::none)
RKPM_SOLVER_INSTANCE(solver_instances::axi, solver_instances::elastic, solver_instances::none)
RKPM_SOLVER_INSTANCE(solver_instances::plane, solver_instances::j2_linear, solver_instances::none)
RKPM_SOLVER_INSTANCE(solver_instances::axi, solver_instances::j2_linear, solver_instances::none)
RKPM_SOLVER_INSTANCE(solver_instances::plane, solver_instances::elastic, solver_instances::effective_frictionless)
RKPM_SOLVER_INSTANCE(solver_instances::plane, solver_instances::elastic, solver_instances::effective_coulomb)
RKPM_SOLVER_INSTANCE(solver_instances::plane, solver_instances::elastic, solver_instances::paper_frictionless)
#endif
#if RKPM_SOLVER_PART(2)
RKPM_SOLVER_INSTANCE(solver_instances::plane, solver_instances::elastic, solver_instances::paper_coulomb)
RKPM_SOLVER_INSTANCE(solver_instances::plane, solver_instances::j2_linear, solver_instances::paper_coulomb)
RKPM_SOLVER_INSTANCE(solver_instances::plane, solver_instances::j2_linear, solver_instances::penalty_coulomb)
RKPM_SOLVER_INSTANCE(solver_instances::axi, solver_instances::j2_linear, solver_instances::paper_coulomb)
RKPM_SOLVER_INSTANCE(solver_instances::axi, solver_instances::j2_linear, solver_instances::effective_coulomb)
RKPM_SOLVER_INSTANCE(solver_instances::axi, solver_instances::j2_linear, solver_instances::penalty_coulomb)
#endif
}  // namespace rkpm
#undef RKPM_SOLVER_INSTANCE
#undef RKPM_SOLVER_PART
#endif
