#pragma once
// shape_table<Dim>: RK shape functions and gradients at a list of evaluation points, in
// compressed sparse rows, built once in the reference configuration (docs/method.md section 9.3).
//   offset    #points+1; the entries of point p are offset[p] .. offset[p+1]-1
//   neighbor  #entries particle index I
//             (offsets and indices in 32 bits, core/types.hpp: the tables are most of a run's memory)
//   N         #entries N_I(x_p)
//   grad      #entries grad N_I(x_p)
//             (empty in a table built with values_only)
// with_free_particles: the rows at the particles with each empty row holding the particle itself.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <rkpm/approximation/rk_shape_functions.hpp>
#include <rkpm/core/execution.hpp>
#include <rkpm/discretization/neighbor_search.hpp>

namespace rkpm {

// A particle index as the tables store it.
using particle_index = stored_index;

template <int Dim>
struct shape_table {
  std::vector<stored_index> offset{0};
  std::vector<particle_index> neighbor;
  std::vector<double> N;
  std::vector<vec<Dim>> grad;

  index_t points() const { return static_cast<index_t>(offset.size()) - 1; }
  index_t entries() const { return static_cast<index_t>(neighbor.size()); }
  // Row p's columns: what the plans and the traversal read of a table (search_rows gives the
  // same without one, discretization/search_rows.hpp).
  std::span<const particle_index> columns(index_t p) const {
    return {neighbor.data() + offset[p], neighbor.data() + offset[p + 1]};
  }

  // Physical value u(x_p) = sum_I N_I(x_p) d_I of a field given by its coefficients d.
  template <class Value>
  // (Zero for a row that cracks left empty, discretization/crack_set.hpp.)
  Value interpolate(index_t p, const std::vector<Value>& d) const {
    Value u = d.front() * 0.0;
    for (index_t e = offset[p]; e < offset[p + 1]; ++e) u += N[e] * d[neighbor[e]];
    return u;
  }
};

// What a table keeps. The table at the particles (physical values, constraint and contact rows)
// reads N only, and on a regular grid about 7 of its 16 entries per particle are particles
// exactly one support away, inside |x - X_I| < a only by rounding, with |N_I| ~ 1e-40: they
// weigh nothing in any sum and took a fifth of that table's memory, its gradients two thirds.
struct shape_table_contents {
  bool gradients = true;    // false: grad stays empty
  double drop_below = 0.0;  // entries with |N_I(x_p)| < drop_below are left out of the rows
};
inline constexpr shape_table_contents values_only{false, 1e-30};

// Renumbers the columns of `table` (particles 0 .. particles-1) to the particles its rows reach,
// in increasing order, and returns the particle of each new column.
template <int Dim>
std::vector<stored_index> compact_columns(shape_table<Dim>& table, index_t particles) {
  std::vector<stored_index> column(particles, -1), particle;
  for (const particle_index I : table.neighbor) column[I] = 0;
  for (index_t I = 0; I < particles; ++I)
    if (column[I] == 0) {
      column[I] = static_cast<stored_index>(particle.size());
      particle.push_back(static_cast<stored_index>(I));
    }
  for (particle_index& I : table.neighbor) I = column[I];
  return particle;
}

// One row's scratch: the neighbours found and their RK values and gradients.
template <int Dim>
struct row_scratch {
  std::vector<index_t> nbr;
  std::vector<double> val;
  std::vector<vec<Dim>> grd;
};

namespace detail {

// row(p, scratch) for every point p in parallel, each thread with its own scratch, 64 rows at
// a time (rows differ in cost); the first error a row throws is thrown again after the loop.
template <int Dim, class Row>
void for_each_point_row(index_t points, Row&& row) {
  exec::parallel_for_each_row<row_scratch<Dim>>(points, 64, row);
}

}  // namespace detail

// Builds the table at `points` for the particles of `search`. Two passes: the neighbour counts
// first (the cell-list query alone) so that the rows are laid out once at their final size,
// then the RK functions of each row written in place: no per-point vectors, no regrowth, so the
// set-up's peak memory is the table itself. A table that drops small entries evaluates the RK
// functions in both passes (the count needs the values). With cracks (the search's), a point
// that sees too few particles for the correction gets an empty row instead of an error: cut
// off from the body by cracks, it has no field (a free particle, docs/method.md section 3.7).
template <Kernel K, Correction C, int Dim>
shape_table<Dim> build_shape_table(const neighbor_search<Dim>& search,
                                   const std::vector<vec<Dim>>& points,
                                   const rk_shape_functions<K, C, Dim>& rk = {},
                                   shape_table_contents contents = {}) {
  const index_t np = static_cast<index_t>(points.size());
  if (search.particles().size() > std::numeric_limits<particle_index>::max())
    fail("{} particles: the shape tables index at most {} particles", search.particles().size(),
         std::numeric_limits<particle_index>::max());
  shape_table<Dim> t;
  t.offset.assign(np + 1, 0);
  const bool dropping = contents.drop_below > 0.0;
  const bool cracked = search.cracks() != nullptr;
  const auto kept = [&](double value) { return !dropping || std::abs(value) >= contents.drop_below; };
  const auto evaluate = [&](index_t p, row_scratch<Dim>& r) {
    if (!cracked) rk.evaluate(points[p], search.particles(), r.nbr, r.val, r.grd);
    else if (!rk.try_evaluate(points[p], search.particles(), r.nbr, r.val, r.grd)) r.nbr.clear();
  };
  // Pass 1: the row lengths.
  detail::for_each_point_row<Dim>(np, [&](index_t p, row_scratch<Dim>& r) {
    search.query(points[p], r.nbr);
    if (!dropping && !cracked) {
      t.offset[p + 1] = static_cast<stored_index>(r.nbr.size());
      return;
    }
    evaluate(p, r);
    t.offset[p + 1] = static_cast<stored_index>(std::ranges::count_if(r.val, kept));
  });
  index_t entries = 0;
  for (index_t p = 0; p < np; ++p) entries += t.offset[p + 1];
  if (entries > std::numeric_limits<stored_index>::max())
    fail("{} evaluation points with {} shape function entries: the tables index at most {} entries "
         "(32-bit offsets); split the body into parts or use fewer particles per support",
         np, entries, std::numeric_limits<stored_index>::max());
  for (index_t p = 0; p < np; ++p) t.offset[p + 1] += t.offset[p];
  t.neighbor.resize(t.offset[np]);
  t.N.resize(t.offset[np]);
  if (contents.gradients) t.grad.resize(t.offset[np]);
  // Pass 2: the rows, in place.
  detail::for_each_point_row<Dim>(np, [&](index_t p, row_scratch<Dim>& r) {
    search.query(points[p], r.nbr);
    evaluate(p, r);
    index_t e = t.offset[p];
    for (std::size_t j = 0; j < r.nbr.size(); ++j) {
      if (!kept(r.val[j])) continue;
      t.neighbor[e] = static_cast<particle_index>(r.nbr[j]);
      t.N[e] = r.val[j];
      if (contents.gradients) t.grad[e] = r.grd[j];
      ++e;
    }
  });
  return t;
}

// The rows at the particles with each empty row (cracks left the particle too few neighbours,
// section 3.7) holding the particle itself, N_I(X_I) = 1: it moves freely.
inline shape_table<2> with_free_particles(shape_table<2> rows) {
  shape_table<2> out;
  out.offset.reserve(rows.offset.size());
  for (index_t I = 0; I < rows.points(); ++I) {
    if (rows.offset[I] == rows.offset[I + 1]) {
      out.neighbor.push_back(static_cast<particle_index>(I));
      out.N.push_back(1.0);
    }
    for (index_t e = rows.offset[I]; e < rows.offset[I + 1]; ++e) {
      out.neighbor.push_back(rows.neighbor[e]);
      out.N.push_back(rows.N[e]);
    }
    out.offset.push_back(static_cast<stored_index>(out.neighbor.size()));
  }
  return out;
}

}  // namespace rkpm

// A program that compiles the shipped kernels' and corrections' tables once (see the header).
#ifdef RKPM_EXTERN_SHAPE_TABLES
#include <rkpm/discretization/shape_table_instances.hpp>
#endif
