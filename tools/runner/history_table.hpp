#pragma once
// The rows of history.csv, kept in memory for the figures and handed back with a run's outcome.

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace rkpm::runner {

struct history_table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  // (column a * scale_a, column b * scale_b) for every row; empty if a column is missing.
  std::vector<std::pair<double, double>> series(const std::string& a, double scale_a, const std::string& b,
                                                double scale_b) const {
    const auto ia = std::find(columns.begin(), columns.end(), a) - columns.begin();
    const auto ib = std::find(columns.begin(), columns.end(), b) - columns.begin();
    std::vector<std::pair<double, double>> out;
    if (ia == static_cast<std::ptrdiff_t>(columns.size()) || ib == static_cast<std::ptrdiff_t>(columns.size()))
      return out;
    for (const auto& r : rows) out.emplace_back(r[ia] * scale_a, r[ib] * scale_b);
    return out;
  }
};

}  // namespace rkpm::runner
