#pragma once
// The discrete model of one body (detail::build_one_model: the points, the shape tables, the VCI
// or SCNI corrections) for the kernels, corrections, rules and geometries rkpm ships, compiled
// once per program instead of once per file (as discretization/shape_table_instances.hpp does
// for the shape tables, which the model calls). Every builder, typed (build_discrete_model,
// build_model_of_bodies, make_solver) or run-time (make_model, whose two geometries
// solver/make_model.hpp declares extern alike), reaches the model through build_one_model, so
// a file that builds models only calls it. A program that wants them once:
//   - compiles the files that define RKPM_INSTANTIATE_MODELS to a part (1: plane strain,
//     2: axisymmetric) and include this header and make_model.hpp, e.g. the project's
//     cmake/models_plane_strain.cpp;
//   - defines RKPM_EXTERN_MODELS in every other file (then discrete_model.hpp includes this
//     header and declares them extern).
// Without either macro nothing changes: the header-only library instantiates as usual. A
// policy outside the lists below (a user's own kernel or rule) is instantiated where it is used.

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/geometry/axisymmetric.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>
#include <rkpm/quadrature/cell_rules.hpp>
#include <rkpm/quadrature/scni.hpp>
#include <rkpm/quadrature/shaped_rules.hpp>
#include <rkpm/quadrature/vci.hpp>
#include <rkpm/solver/discrete_model.hpp>

#if defined(RKPM_INSTANTIATE_MODELS)
#define RKPM_MODEL_EXTERN
#define RKPM_MODEL_PART(n) (RKPM_INSTANTIATE_MODELS == n)
#elif defined(RKPM_EXTERN_MODELS)
#define RKPM_MODEL_EXTERN extern
#define RKPM_MODEL_PART(n) 1
#endif

#ifdef RKPM_MODEL_EXTERN
// One rule in geometry G, every kernel and correction.
#define RKPM_MODEL_INSTANCE(K, C, Q, G) \
  RKPM_MODEL_EXTERN template discrete_model detail::build_one_model<K, C, Q, G>(particle_set<2>, background_mesh, double, \
                                                                                const quadrature_points*);
#define RKPM_MODEL_INSTANCES_OF_RULE(Q, G)                                                 \
  RKPM_MODEL_INSTANCE(kernel::cubic_spline, correction::linear, Q, G)                  \
  RKPM_MODEL_INSTANCE(kernel::cubic_spline, correction::quadratic, Q, G)               \
  RKPM_MODEL_INSTANCE(kernel::quartic_spline, correction::linear, Q, G)                \
  RKPM_MODEL_INSTANCE(kernel::quartic_spline, correction::quadratic, Q, G)
// Every shipped rule in geometry G (policies::all_quadratures; make_model.hpp checks the count).
#define RKPM_MODEL_INSTANCES_OF_GEOMETRY(G)                                                     \
  RKPM_MODEL_INSTANCES_OF_RULE(quadrature::q2, G)                                               \
  RKPM_MODEL_INSTANCES_OF_RULE(quadrature::q4, G)                                               \
  RKPM_MODEL_INSTANCES_OF_RULE(quadrature::q9, G)                                               \
  RKPM_MODEL_INSTANCES_OF_RULE(quadrature::q2_split, G)                                         \
  RKPM_MODEL_INSTANCES_OF_RULE(quadrature::q2_tri, G)                                           \
  RKPM_MODEL_INSTANCES_OF_RULE(quadrature::q2_vci, G)                                           \
  RKPM_MODEL_INSTANCES_OF_RULE(quadrature::q4_vci, G)                                           \
  RKPM_MODEL_INSTANCES_OF_RULE(quadrature::vci<quadrature::q2_split>, G)                        \
  RKPM_MODEL_INSTANCES_OF_RULE(quadrature::vci<quadrature::q2_tri>, G)                          \
  RKPM_MODEL_INSTANCES_OF_RULE(quadrature::scni<>, G)                                           \
  RKPM_MODEL_INSTANCES_OF_RULE(quadrature::scni_plain, G)

namespace rkpm {
#if RKPM_MODEL_PART(1)
RKPM_MODEL_INSTANCES_OF_GEOMETRY(geometry::plane_strain)
#endif
#if RKPM_MODEL_PART(2)
RKPM_MODEL_INSTANCES_OF_GEOMETRY(geometry::axisymmetric)
#endif
}  // namespace rkpm

#undef RKPM_MODEL_INSTANCES_OF_GEOMETRY
#undef RKPM_MODEL_INSTANCES_OF_RULE
#undef RKPM_MODEL_INSTANCE
#undef RKPM_MODEL_EXTERN
#undef RKPM_MODEL_PART
#endif
