#pragma once
// scni<Beta, EdgePoints>: stabilized conforming nodal integration (Chen, Wu, Yoon, You 2001,
// IJNME 50:435) with the stabilization of modified SCNI (Puso, Chen, Zywicz, Elmer 2008,
// IJNME 74:416); docs/method.md section 3.6, (19d)-(19h). A NodalRule
// (concepts/quadrature.hpp): no points per cell, but one smoothing cell per mesh node (the
// node's median dual cell, the parts of the cells around it cut at the edge midpoints and the
// cell centres), on which the gradients are smoothed, once, in the reference configuration,
// by discretization/smoothing_cells.hpp when build_discrete_model sees a NodalRule:
//   Beta = 0   pure SCNI: one point per node, at the centroid of its smoothing cell, with the
//              smoothed gradient (19e); name "scni_plain"
//   Beta > 0   one point per part (sub-cell) of each smoothing cell, at the part's centroid,
//              with the trial and test gradient g_cell + Beta (g_part - g_cell) (19g); for
//              linear elasticity the stiffness is SCNI's plus Puso's stabilization with
//              alpha = Beta^2 (plane strain). The default, 0.85 (name "scni"), is the one the
//              spectrum test (tests/numeric/integration_spectrum.cpp) chose.
// EdgePoints: Gauss-Legendre points on each straight segment of a smoothing cell's boundary.
// The integration constraint (19a) holds to round-off for every Beta.

#include <string_view>

#include <rkpm/concepts/quadrature.hpp>

namespace rkpm::quadrature {

inline constexpr double scni_default_stabilization = 0.85;

template <double Beta = scni_default_stabilization, int EdgePoints = 3>
struct scni {
  static_assert(Beta >= 0.0 && Beta <= 1.0, "scni<Beta>: the stabilization Beta must lie in [0, 1]");
  static_assert(EdgePoints >= 2 && EdgePoints <= 6, "scni<Beta, EdgePoints>: 2 to 6 Gauss points per segment");
  static constexpr std::string_view name = Beta == 0.0                          ? std::string_view("scni_plain")
                                           : Beta == scni_default_stabilization ? std::string_view("scni")
                                                                                : std::string_view("scni_custom");
  static constexpr bool smooths_gradients = true;
  static constexpr double stabilization = Beta;
  static constexpr int edge_points = EdgePoints;
};

using scni_plain = scni<0.0>;

}  // namespace rkpm::quadrature
