#pragma once
// shape_table<Dim>: RK shape functions and gradients at a list of evaluation points, in
// compressed sparse rows, built once in the reference configuration (docs/method.md section 9.3).
//   offset    #points+1; the entries of point p are offset[p] .. offset[p+1]-1
//   neighbor  #entries particle index_t I
//   N         #entries N_I(x_p)
//   grad      #entries grad N_I(x_p)
// The transpose lists, for each particle, the entries that touch it, so that a scatter to
// particles can run in parallel without atomics.

#include <vector>

#include <rkpm/approximation/rk_shape_functions.hpp>
#include <rkpm/discretization/neighbor_search.hpp>

namespace rkpm {

template <int Dim>
struct shape_table {
  std::vector<index_t> offset{0};
  std::vector<index_t> neighbor;
  std::vector<double> N;
  std::vector<vec<Dim>> grad;

  index_t points() const { return static_cast<index_t>(offset.size()) - 1; }
  index_t entries() const { return static_cast<index_t>(neighbor.size()); }

  // Physical value u(x_p) = sum_I N_I(x_p) d_I of a field given by its coefficients d.
  template <class Value>
  Value interpolate(index_t p, const std::vector<Value>& d) const {
    Value u = d[neighbor[offset[p]]] * 0.0;
    for (index_t e = offset[p]; e < offset[p + 1]; ++e) u += N[e] * d[neighbor[e]];
    return u;
  }
};

// Per particle I: the entries e of a shape_table with neighbor[e] == I, and their points.
struct shape_table_transpose {
  std::vector<index_t> offset{0};  // #particles+1
  std::vector<index_t> entry;      // #entries, index_t into the forward table
  std::vector<index_t> point;      // #entries, the evaluation point of that entry
};

template <int Dim>
shape_table_transpose transpose(const shape_table<Dim>& table, index_t particles) {
  shape_table_transpose t;
  t.offset.assign(particles + 1, 0);
  for (index_t I : table.neighbor) ++t.offset[I + 1];
  for (index_t I = 0; I < particles; ++I) t.offset[I + 1] += t.offset[I];
  t.entry.resize(table.entries());
  t.point.resize(table.entries());
  std::vector<index_t> fill(t.offset.begin(), t.offset.end() - 1);
  for (index_t p = 0; p < table.points(); ++p)
    for (index_t e = table.offset[p]; e < table.offset[p + 1]; ++e) {
      const index_t slot = fill[table.neighbor[e]]++;
      t.entry[slot] = e;
      t.point[slot] = p;
    }
  return t;
}

// Builds the table at `points` for the particles of `search`.
template <Kernel K, Correction C, int Dim>
shape_table<Dim> build_shape_table(const neighbor_search<Dim>& search,
                                   const std::vector<vec<Dim>>& points,
                                   const rk_shape_functions<K, C, Dim>& rk = {}) {
  const index_t np = static_cast<index_t>(points.size());
  std::vector<std::vector<index_t>> nbr(np);
  std::vector<std::vector<double>> val(np);
  std::vector<std::vector<vec<Dim>>> grd(np);
  std::string first_error;
#pragma omp parallel for schedule(dynamic, 64)
  for (index_t p = 0; p < np; ++p) {
    try {
      search.query(points[p], nbr[p]);
      rk.evaluate(points[p], search.particles(), nbr[p], val[p], grd[p]);
    } catch (const error& e) {
#pragma omp critical(rkpm_shape_table_error)
      if (first_error.empty()) first_error = e.what();
    }
  }
  if (!first_error.empty()) throw error(first_error);
  shape_table<Dim> t;
  t.offset.resize(np + 1);
  t.offset[0] = 0;
  for (index_t p = 0; p < np; ++p) t.offset[p + 1] = t.offset[p] + static_cast<index_t>(nbr[p].size());
  t.neighbor.reserve(t.offset[np]);
  t.N.reserve(t.offset[np]);
  t.grad.reserve(t.offset[np]);
  for (index_t p = 0; p < np; ++p) {
    t.neighbor.insert(t.neighbor.end(), nbr[p].begin(), nbr[p].end());
    t.N.insert(t.N.end(), val[p].begin(), val[p].end());
    t.grad.insert(t.grad.end(), grd[p].begin(), grd[p].end());
  }
  return t;
}

}  // namespace rkpm

// A program that compiles the shipped kernels' and corrections' tables once (see the header).
#ifdef RKPM_EXTERN_SHAPE_TABLES
#include <rkpm/discretization/shape_table_instances.hpp>
#endif
