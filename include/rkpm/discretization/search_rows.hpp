#pragma once
// search_rows<Dim>: the columns that a shape table's rows would have at given positions (the
// particles whose supports hold each position, discretization/neighbor_search.hpp), found when
// asked and never stored. The plans of a run on several processes and the force loop's
// traversal read only a table's columns, never its values (ColumnRows below): from these rows
// they are made for the whole model without its tables, 8 bytes per entry that a set-up on
// several processes never holds (parallel/rank_setup.hpp). Row q equals row q of
// build_shape_table(search, positions) without values_only's dropping and without cracks: the
// same particles in the same order. With several bodies (body_searches) each row holds only the
// particles of its position's body, as a model of several bodies builds each body's table on its
// own (solver/body_models.hpp): a body's search holds only its particles, and a query returns
// them ascending, so the rows are those of the body's own search, renumbered.

#include <concepts>
#include <functional>
#include <span>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/discretization/neighbor_search.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm {

// Rows whose columns can be read one at a time: a shape_table, or search_rows. The span may
// be valid only until the next call.
template <class R>
concept ColumnRows = requires(const R& r, index_t q) {
  { r.points() } -> std::convertible_to<index_t>;
  { r.columns(q) } -> std::convertible_to<std::span<const particle_index>>;
};

// One neighbour search per body: body b's finds only b's particles (by their indices in the set).
template <int Dim>
class body_searches {
 public:
  // `body`: each particle's body, 0 .. bodies - 1 (empty: one body, one search over all).
  // The particles are kept by pointer: they must outlive the searches.
  body_searches(const particle_set<Dim>& particles, const std::vector<index_t>& body, index_t bodies) {
    if (body.empty()) {
      search_.emplace_back(particles);
      return;
    }
    if (static_cast<index_t>(body.size()) != particles.size())
      fail("body searches: {} bodies given for {} particles; give each particle's body", body.size(), particles.size());
    std::vector<std::vector<index_t>> of(bodies);
    for (index_t I = 0; I < particles.size(); ++I) {
      if (body[I] < 0 || body[I] >= bodies) fail("body searches: particle {} is in body {} of {}", I, body[I], bodies);
      of[body[I]].push_back(I);
    }
    for (const std::vector<index_t>& only : of) search_.emplace_back(particles, nullptr, only);
  }
  index_t count() const { return static_cast<index_t>(search_.size()); }
  const neighbor_search<Dim>& of(index_t b) const { return search_[b]; }

 private:
  std::vector<neighbor_search<Dim>> search_;
};

template <int Dim>
class search_rows {
 public:
  // The search, the searches and the positions are kept by pointer: they must outlive the rows.
  search_rows(const neighbor_search<Dim>& search, const std::vector<vec<Dim>>& positions)
      : search_(&search), positions_(&positions) {
    if (search.cracks())
      fail("search rows: the rows of a cracked body depend on the shape functions (free particles, section "
           "3.7); build the tables of a body with cracks");
  }
  // Row q within body body_of(q) (unused with one body).
  search_rows(const body_searches<Dim>& searches, const std::vector<vec<Dim>>& positions,
              std::function<index_t(index_t)> body_of)
      : search_(&searches.of(0)), positions_(&positions) {
    if (searches.count() > 1) {
      searches_ = &searches;
      body_of_ = std::move(body_of);
    }
  }
  index_t points() const { return static_cast<index_t>(positions_->size()); }
  std::span<const particle_index> columns(index_t q) const {
    const neighbor_search<Dim>& search = searches_ ? searches_->of(body_of_(q)) : *search_;
    search.query((*positions_)[q], found_);
    row_.assign(found_.begin(), found_.end());
    return row_;
  }

 private:
  const neighbor_search<Dim>* search_;
  const body_searches<Dim>* searches_ = nullptr;
  std::function<index_t(index_t)> body_of_;
  const std::vector<vec<Dim>>* positions_;
  mutable std::vector<index_t> found_;
  mutable std::vector<particle_index> row_;
};

}  // namespace rkpm
