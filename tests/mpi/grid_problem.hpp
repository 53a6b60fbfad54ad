#pragma once
// The small problem of the decomposition tests (tests/mpi): a 12 x 8 particle grid on a
// 5.5 x 3.5 mm box, cubic kernel (support factor 2), linear correction, Q4 points of the grid's
// cells (77 cells, 308 points), and the shape table at the points. Plus partitions that force a
// cut along a chosen line, and a smooth displacement field that is not a polynomial.

#include <cmath>
#include <vector>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/discretization/quadrature_points.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/geometry/plane_strain.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/parallel/partition.hpp>
#include <rkpm/quadrature/cell_rules.hpp>

namespace rkpm::test {

struct grid_problem {
  static constexpr double width = 5.5e-3, height = 3.5e-3;
  particle_set<2> particles;
  quadrature_points points;
  shape_table<2> table;

  explicit grid_problem(int nx = 12, int ny = 8) {
    const vec2 lo(0.0, 0.0), hi(width, height);
    const Eigen::Vector2i n(nx, ny);
    particles = make_grid_particles<2>(lo, hi, n, 2.0);
    points = make_quadrature_points<quadrature::q4, geometry::plane_strain>(make_grid_mesh(lo, hi, n));
    const neighbor_search<2> search(particles);
    const rk_shape_functions<kernel::cubic_spline, correction::linear, 2> rk(default_max_moment_condition);
    table = build_shape_table<kernel::cubic_spline, correction::linear, 2>(search, points.position, rk);
  }
  index_t size() const { return particles.size(); }

  // Parts cut by lines parallel to a * x + b * y = const, in `parts` stripes of equal width
  // over the box: a cut that crosses the supports of many points at an angle to the grid.
  parallel::particle_partition stripes(index_t parts, double a = 1.0, double b = 0.6) const {
    std::vector<stored_index> part(size());
    const double lo = std::min(0.0, a * width) + std::min(0.0, b * height);
    const double hi = std::max(0.0, a * width) + std::max(0.0, b * height);
    for (index_t I = 0; I < size(); ++I) {
      const double s = (a * particles.position[I][0] + b * particles.position[I][1] - lo) / (hi - lo);
      part[I] = static_cast<stored_index>(std::min<index_t>(parts - 1, static_cast<index_t>(s * static_cast<double>(parts))));
    }
    return parallel::given_partition(std::move(part), parts);
  }

  // A smooth displacement of particle I, about 1% strain, with no polynomial structure.
  vec2 displacement(index_t I) const {
    const vec2& X = particles.position[I];
    const double x = X[0] / width, y = X[1] / height;
    return 1e-5 * vec2(std::sin(2.3 * x + 0.7) * std::cos(1.9 * y) + 0.31 * x * x * y,
                       std::cos(1.7 * x * y + 0.2) - 0.43 * std::sin(3.1 * y + x));
  }
};

}  // namespace rkpm::test
