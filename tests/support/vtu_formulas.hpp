#pragma once
// The snapshot whose every value tests/unit/io/check_vtu.py recomputes (its expected()): point i
// at (i / 8 - 3/7, -i/3 + 1e-7) with the arrays eps_p, u, sigma and "det F <J>" as closed
// formulas in i. snapshot_of(ids) gives the points of the given indices in that order (a
// process's piece of a snapshot, tests/mpi/pvtu.cpp), with their indices as the array
// "particle" when asked.

#include <vector>

#include <rkpm/core/types.hpp>
#include <rkpm/io/point_data.hpp>

namespace rkpm::test {

struct vtu_snapshot {
  std::vector<vec2> points;
  io::point_data data;
};

inline vtu_snapshot snapshot_of(const std::vector<int>& ids, bool with_ids = false) {
  vtu_snapshot s;
  const std::size_t n = ids.size();
  std::vector<double> eps(n), det(n), id(n);
  std::vector<vec2> u(n);
  std::vector<mat3> sigma(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double i = ids[k];
    s.points.emplace_back(i * 0.125 - 3.0 / 7.0, -i / 3.0 + 1e-7);
    eps[k] = i / 7.0 - 2.5;
    u[k] = vec2(i * 1e-6, -i / 3.0);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) sigma[k](r, c) = 1e8 * (i + 1.0) + 10.0 * r + c + 0.1;
    det[k] = 1.0 + i / 1024.0;
    id[k] = i;
  }
  s.data.add("eps_p", eps).add("u", u).add("sigma", sigma).add("det F <J>", det);
  if (with_ids) s.data.add("particle", id);
  return s;
}

// Points 0 .. n-1.
inline vtu_snapshot snapshot_of(int n) {
  std::vector<int> ids(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) ids[static_cast<std::size_t>(i)] = i;
  return snapshot_of(ids);
}

}  // namespace rkpm::test
