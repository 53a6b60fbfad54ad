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
// The table of shipped rules: X(Q, G) for each, in policies::all_quadratures' order. A macro,
// because an explicit instantiation declaration must name its types in the source (a Hana list
// can call a template for each type, not declare one extern); what the list can do is check the
// table: detail::model_table_rules, the rules listed here, must be policies::all_quadratures
// exactly (make_model.hpp), so a rule added to one and not the other stops the build.
#define RKPM_MODEL_RULES(X, G)                    \
  X(quadrature::q2, G)                            \
  X(quadrature::q4, G)                            \
  X(quadrature::q9, G)                            \
  X(quadrature::q2_split, G)                      \
  X(quadrature::q2_tri, G)                        \
  X(quadrature::q2_vci, G)                        \
  X(quadrature::q4_vci, G)                        \
  X(quadrature::vci<quadrature::q2_split>, G)     \
  X(quadrature::vci<quadrature::q2_tri>, G)       \
  X(quadrature::scni<>, G)                        \
  X(quadrature::scni_plain, G)
#define RKPM_MODEL_LISTED_RULE(Q, G) Q,

namespace rkpm::detail {
template <class... Q>
struct model_table {};
// The table's rules as a type list (void closes it).
using model_table_rules = model_table<RKPM_MODEL_RULES(RKPM_MODEL_LISTED_RULE, ) void>;
}  // namespace rkpm::detail

namespace rkpm {
#if RKPM_MODEL_PART(1)
RKPM_MODEL_RULES(RKPM_MODEL_INSTANCES_OF_RULE, geometry::plane_strain)
#endif
#if RKPM_MODEL_PART(2)
RKPM_MODEL_RULES(RKPM_MODEL_INSTANCES_OF_RULE, geometry::axisymmetric)
#endif
}  // namespace rkpm

#undef RKPM_MODEL_RULES
#undef RKPM_MODEL_LISTED_RULE
#undef RKPM_MODEL_INSTANCES_OF_RULE
#undef RKPM_MODEL_INSTANCE
#undef RKPM_MODEL_EXTERN
#undef RKPM_MODEL_PART
#endif
