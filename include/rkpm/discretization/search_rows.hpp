#pragma once
// search_rows<Dim>: the columns that a shape table's rows would have at given positions (the
// particles whose supports hold each position, discretization/neighbor_search.hpp), found when
// asked and never stored. The plans of a run on several processes and the force loop's
// traversal read only a table's columns, never its values (ColumnRows below): from these rows
// they are made for the whole model without its tables, 8 bytes per entry that a set-up on
// several processes never holds (parallel/rank_setup.hpp). Row q equals row q of
// build_shape_table(search, positions) without values_only's dropping and without cracks: the
// same particles in the same order.

#include <concepts>
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

template <int Dim>
class search_rows {
 public:
  // Both are kept by pointer: they must outlive the rows.
  search_rows(const neighbor_search<Dim>& search, const std::vector<vec<Dim>>& positions)
      : search_(&search), positions_(&positions) {
    if (search.cracks())
      fail("search rows: the rows of a cracked body depend on the shape functions (free particles, section "
           "3.7); build the tables of a body with cracks");
  }
  index_t points() const { return static_cast<index_t>(positions_->size()); }
  std::span<const particle_index> columns(index_t q) const {
    search_->query((*positions_)[q], found_);
    row_.assign(found_.begin(), found_.end());
    return row_;
  }

 private:
  const neighbor_search<Dim>* search_;
  const std::vector<vec<Dim>>* positions_;
  mutable std::vector<index_t> found_;
  mutable std::vector<particle_index> row_;
};

}  // namespace rkpm
