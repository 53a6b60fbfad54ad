#pragma once
// pairwise_covering(sizes): rows of values, one per family (a family has sizes[f] values),
// in which every pair of values from two different families appears at least once: the
// covering set of a test matrix (docs/method.md section 9.2). Computed at compile time by
// in-parameter-order growth (IPOG): all pairs of the two largest families, then one family at
// a time, each row given the value that covers the most pairs not yet covered (the least used
// value on ties), and rows added for what is left. The other families are tried in every order
// and the shortest table kept. For the shipped policies this is the lower bound, the product
// of the two largest family sizes.

#include <array>
#include <cstddef>

namespace rkpm {

template <std::size_t Families, std::size_t MaxRows = 64>
struct covering_table {
  std::array<std::array<std::size_t, Families>, MaxRows> rows{};
  std::size_t count = 0;
};

namespace detail {

inline constexpr std::size_t unset = static_cast<std::size_t>(-1);
inline constexpr std::size_t max_family_size = 8;

// One IPOG growth with the families taken in `order` (the two largest first).
template <std::size_t N, std::size_t MaxRows>
constexpr covering_table<N, MaxRows> grow_covering(const std::array<std::size_t, N>& sizes,
                                                   const std::array<std::size_t, N>& order) {
  covering_table<N, MaxRows> t;
  for (std::size_t a = 0; a < sizes[order[0]]; ++a)
    for (std::size_t b = 0; b < sizes[order[1]]; ++b) {
      auto& row = t.rows[t.count++];
      row.fill(unset);
      row[order[0]] = a;
      row[order[1]] = b;
    }
  for (std::size_t k = 2; k < N; ++k) {
    const std::size_t f = order[k];
    // covered[g][w][v]: some row has family g at w and family f at v.
    std::array<std::array<std::array<bool, max_family_size>, max_family_size>, N> covered{};
    // Across: each row takes the value of f that covers the most new pairs.
    for (std::size_t i = 0; i < t.count; ++i) {
      auto& row = t.rows[i];
      std::size_t best = 0, best_fresh = 0, best_uses = MaxRows;
      for (std::size_t v = 0; v < sizes[f]; ++v) {
        std::size_t fresh = 0, uses = 0;
        for (std::size_t j = 0; j < k; ++j)
          if (row[order[j]] != unset && !covered[order[j]][row[order[j]]][v]) ++fresh;
        for (std::size_t p = 0; p < i; ++p) uses += t.rows[p][f] == v;
        if (fresh > best_fresh || (fresh == best_fresh && uses < best_uses)) {
          best = v;
          best_fresh = fresh;
          best_uses = uses;
        }
      }
      row[f] = best;
      for (std::size_t j = 0; j < k; ++j)
        if (row[order[j]] != unset) covered[order[j]][row[order[j]]][best] = true;
    }
    // Down: each pair still missing goes into a row with f = v whose g is free, or a new row.
    for (std::size_t j = 0; j < k; ++j) {
      const std::size_t g = order[j];
      for (std::size_t w = 0; w < sizes[g]; ++w)
        for (std::size_t v = 0; v < sizes[f]; ++v) {
          if (covered[g][w][v]) continue;
          std::size_t i = 0;
          while (i < t.count && !(t.rows[i][f] == v && t.rows[i][g] == unset)) ++i;
          if (i == t.count) {
            t.rows[t.count].fill(unset);
            t.rows[t.count++][f] = v;
          }
          t.rows[i][g] = w;
          covered[g][w][v] = true;
        }
    }
  }
  for (std::size_t i = 0; i < t.count; ++i)
    for (auto& value : t.rows[i])
      if (value == unset) value = 0;  // a free value: any will do
  return t;
}

// The next permutation of order[from..] in increasing order; false after the last.
template <std::size_t N>
constexpr bool next_order(std::array<std::size_t, N>& a, std::size_t from) {
  std::size_t i = N - 1;
  while (i > from && a[i - 1] >= a[i]) --i;
  if (i == from) return false;
  std::size_t j = N - 1;
  while (a[j] <= a[i - 1]) --j;
  const std::size_t x = a[i - 1];
  a[i - 1] = a[j];
  a[j] = x;
  for (std::size_t l = i, r = N - 1; l < r; ++l, --r) {
    const std::size_t y = a[l];
    a[l] = a[r];
    a[r] = y;
  }
  return true;
}

}  // namespace detail

template <std::size_t N, std::size_t MaxRows = 64>
constexpr covering_table<N, MaxRows> pairwise_covering(const std::array<std::size_t, N>& sizes) {
  static_assert(N >= 2, "pairwise_covering needs at least two families");
  for (std::size_t s : sizes)
    if (s == 0 || s > detail::max_family_size) throw "pairwise_covering: a family has 0 or more than 8 values";
  // The families by size, largest first (stable), then the rest in increasing index order.
  std::array<std::size_t, N> order{};
  for (std::size_t i = 0; i < N; ++i) order[i] = i;
  for (std::size_t i = 1; i < N; ++i)
    for (std::size_t j = i; j > 0 && sizes[order[j]] > sizes[order[j - 1]]; --j) {
      const std::size_t x = order[j];
      order[j] = order[j - 1];
      order[j - 1] = x;
    }
  for (std::size_t i = 3; i < N; ++i)
    for (std::size_t j = i; j > 2 && order[j] < order[j - 1]; --j) {
      const std::size_t x = order[j];
      order[j] = order[j - 1];
      order[j - 1] = x;
    }
  covering_table<N, MaxRows> best = detail::grow_covering<N, MaxRows>(sizes, order);
  while (detail::next_order(order, 2)) {
    const covering_table<N, MaxRows> t = detail::grow_covering<N, MaxRows>(sizes, order);
    if (t.count < best.count) best = t;
  }
  return best;
}

}  // namespace rkpm
