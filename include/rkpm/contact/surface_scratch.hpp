#pragma once
// What the contact passes on deformable surfaces share (body_contact.hpp, tool_vertex_contact.hpp;
// docs/method.md section 6.9): the physical positions and velocities of surface particles, the
// row of a contact point on a segment a-b, c_I = (1 - lambda) N_I(X_a) + lambda N_I(X_b), the
// shared effective mass (61a) over such rows, and the force increments spread to the
// coefficients through rows and applied as (60) (coefficient_increments, which the rigid tools'
// pass of particle_to_segment.hpp uses too). The surfaces themselves are the model's
// (model_bodies::surface). Per-particle scratch sized once, so a step allocates nothing.

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm::contact {

// Force increments on the coefficients, gathered through shape-function rows and applied as
// (60); only the coefficients touched are visited. Used by every contact pass. Sized by the
// rows' columns: the particles, or the particles some rows reach, numbered from 0 (the rigid
// tools' slave table, particle_to_segment.hpp), which apply() maps back.
class coefficient_increments {
 public:
  void resize(index_t columns) {
    slot_.assign(columns, -1);
    dforce_.assign(columns, vec2::Zero());
    touched_.assign(columns, 0);
    touched_count_ = 0;
  }

  // f_I += scale N_I(X_J) df over row J of `rows`.
  void spread(const shape_table<2>& rows, index_t J, double scale, const vec2& df) {
    if (scale == 0.0) return;
    for (index_t e = rows.offset[J]; e < rows.offset[J + 1]; ++e) {
      const index_t I = rows.neighbor[e];
      stored_index& s = slot_[I];
      if (s < 0) {
        s = static_cast<stored_index>(touched_count_);
        touched_[touched_count_++] = static_cast<stored_index>(I);
      }
      dforce_[s] += scale * rows.N[e] * df;
    }
  }

  // (60): v_I += dt f_I / m_I, d_I += dt^2 f_I / m_I for the coefficients spread to; then zero.
  // particle: the particle of each column (empty: the columns are the particles).
  void apply(std::span<const double> m, double dt, std::vector<vec2>& d, std::vector<vec2>& v,
             std::span<const stored_index> particle = {}) {
    for (index_t s = 0; s < touched_count_; ++s) {
      const index_t c = touched_[s];
      const index_t I = particle.empty() ? c : particle[c];
      const vec2 da = dforce_[s] / m[I];
      v[I] += dt * da;
      d[I] += dt * dt * da;
      dforce_[s].setZero();
      slot_[c] = -1;
    }
    touched_count_ = 0;
  }

 private:
  std::vector<stored_index> slot_;     // #columns: where column c's increment is, -1 if untouched
  std::vector<vec2> dforce_;           // in the order first touched
  std::vector<stored_index> touched_;  // the column of each slot
  index_t touched_count_ = 0;
};

class surface_scratch {
 public:
  void resize(index_t particles) {
    x.assign(particles, vec2::Zero());
    w.assign(particles, vec2::Zero());
    coefficient_.assign(particles, 0.0);
    coverage_.assign(particles, 0.0);
    increments_.resize(particles);
  }

  // x_I = X_I + sum_J N_J(X_I) d_J and w_I = sum_J N_J(X_I) v_J.
  void physical_state(const shape_table<2>& rows, std::span<const vec2> X, index_t I, const std::vector<vec2>& d,
                      const std::vector<vec2>& v) {
    vec2 u = vec2::Zero(), s = vec2::Zero();
    for (index_t e = rows.offset[I]; e < rows.offset[I + 1]; ++e) {
      u += rows.N[e] * d[rows.neighbor[e]];
      s += rows.N[e] * v[rows.neighbor[e]];
    }
    x[I] = X[I] + u;
    w[I] = s;
  }

  // visit(I, c_I) for each coefficient of the contact point (1 - lambda) a + lambda b, each I once.
  template <class Visit>
  void visit_point(const shape_table<2>& rows, index_t a, index_t b, double lambda, Visit&& visit) {
    for (const auto& [vertex, weight] : {std::pair{a, 1.0 - lambda}, std::pair{b, lambda}})
      for (index_t e = rows.offset[vertex]; e < rows.offset[vertex + 1]; ++e)
        coefficient_[rows.neighbor[e]] += weight * rows.N[e];
    for (index_t vertex : {a, b})
      for (index_t e = rows.offset[vertex]; e < rows.offset[vertex + 1]; ++e) {
        double& c = coefficient_[rows.neighbor[e]];
        if (c != 0.0) visit(rows.neighbor[e], c);
        c = 0.0;
      }
  }

  // (61a) for contacts given by visit_row(q, visit) over q in [first, end): mass(q) is set to
  // 1 / sum_I |r_qI| S_I / m_I, S_I = sum over the contacts p of |r_pI|.
  template <class VisitRow, class SetMass>
  void shared_masses(index_t first, index_t end, std::span<const double> m, VisitRow&& visit_row, SetMass&& mass) {
    for (index_t q = first; q < end; ++q) visit_row(q, [&](index_t I, double r) { coverage_[I] += std::abs(r); });
    for (index_t q = first; q < end; ++q) {
      double s = 0.0;
      visit_row(q, [&](index_t I, double r) { s += std::abs(r) * coverage_[I] / m[I]; });
      mass(q, 1.0 / s);
    }
    for (index_t q = first; q < end; ++q) visit_row(q, [&](index_t I, double) { coverage_[I] = 0.0; });
  }

  void spread(const shape_table<2>& rows, index_t J, double scale, const vec2& df) {
    increments_.spread(rows, J, scale, df);
  }
  void apply(std::span<const double> m, double dt, std::vector<vec2>& d, std::vector<vec2>& v) {
    increments_.apply(m, dt, d, v);
  }

  std::vector<vec2> x, w;  // physical positions and velocities (surface particles only)

 private:
  std::vector<double> coefficient_, coverage_;
  coefficient_increments increments_;
};

}  // namespace rkpm::contact
