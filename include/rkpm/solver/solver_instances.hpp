#pragma once
// explicit_solver for the configurations that the project's programs (tests, tutorials,
// benchmarks) use in several files, compiled once instead of once per file (as
// discretization/shape_table_instances.hpp does for the shape tables). The solver's set-up and
// step are most of a program's compile time, and most of these types are used by two to eight
// files. A program that wants them once:
//   - compiles the files that define RKPM_INSTANTIATE_SOLVERS to a part number (1 to 3) and
//     include this header (the explicit instantiation definitions of that part): the project's
//     cmake/solvers_<part>.cpp, in its library rkpm_instances;
//   - defines RKPM_EXTERN_SOLVERS in every other file (then make_solver.hpp includes this
//     header and declares them extern, so those files only call their set-up and step).
// Without either macro nothing changes: the header-only library instantiates as usual. A
// configuration missing from the list is instantiated where it is used, as before.

#include <rkpm/contact/none.hpp>
#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/material/elastic.hpp>
#include <rkpm/material/j2_plasticity.hpp>
#include <rkpm/material/johnson_cook.hpp>
#include <rkpm/material/rankine_fracture.hpp>
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
using j2_power = material::j2_plasticity<material::hardening::power_law>;
using johnson_cook = material::johnson_cook;
using rankine = material::rankine_fracture;
using none = contact::none;
using paper_coulomb = contact::particle_to_segment<e::paper, f::coulomb>;
using paper_frictionless = contact::particle_to_segment<e::paper, f::frictionless>;
using effective_coulomb = contact::particle_to_segment<e::effective_mass, f::coulomb>;
using effective_frictionless = contact::particle_to_segment<e::effective_mass, f::frictionless>;
using penalty_coulomb = contact::particle_to_segment<e::penalty, f::coulomb>;
}  // namespace rkpm::solver_instances

namespace rkpm {
// In three parts of about equal compile time, built side by side with the library's other
// instances (each file compiled costs seconds of its own before its instantiations).
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
#if RKPM_SOLVER_PART(3)
RKPM_SOLVER_INSTANCE(solver_instances::axi, solver_instances::j2_linear, solver_instances::paper_frictionless)
RKPM_SOLVER_INSTANCE(solver_instances::axi, solver_instances::j2_power, solver_instances::paper_coulomb)
RKPM_SOLVER_INSTANCE(solver_instances::plane, solver_instances::j2_linear, solver_instances::effective_coulomb)
RKPM_SOLVER_INSTANCE(solver_instances::plane, solver_instances::johnson_cook, solver_instances::paper_coulomb)
RKPM_SOLVER_INSTANCE(solver_instances::plane, solver_instances::rankine, solver_instances::none)
#endif
}  // namespace rkpm
#undef RKPM_SOLVER_INSTANCE
#undef RKPM_SOLVER_PART
#endif
