#pragma once
// point_data: the named per-particle arrays of a VTK snapshot (io/vtk.hpp writes them), given,
// deferred (computed when the writer reaches them) or filled (made piecewise as they are written).

#include <cstddef>
#include <algorithm>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm::io {

// fill(first, n, out): values first .. first + n - 1 of an array made piecewise, into out.
template <class T>
using value_filler = std::function<void(std::size_t first, std::size_t n, T* out)>;

// All `count` values of an array made piecewise (prepare() returns its filler), at once.
template <class T>
std::vector<T> filled_values(std::size_t count, const std::function<value_filler<T>()>& prepare) {
  std::vector<T> values(count);
  if (count > 0) prepare()(0, count, values.data());
  return values;
}

// Named per-particle arrays of one snapshot, in the order they were added (ParaView lists them
// in that order). Values are copied: a snapshot is written once, not every step. A deferred
// array is computed only when write_vtu reaches it and let go once encoded, so that a writer of
// many large arrays holds one of them raw at a time (the runner's snapshots at 10^6 particles).
class point_data {
 public:
  using producer = std::function<std::vector<double>()>;
  using filler = value_filler<double>;  // fill(first, n, out): values first .. first + n - 1
  struct array {
    std::string name;
    int components;              // 1 scalar, 3 vector (2D + zero z), 9 tensor (row-major)
    std::vector<double> values;  // #points * components, point-major; empty while deferred
    producer produce = {};       // set for a deferred or filled array: returns its values
    std::function<filler()> prepare = {};  // set for a filled array: what fills it piecewise
  };

  // values  #points scalars
  point_data& add(std::string name, std::span<const double> values) {
    return add_values(std::move(name), 1, std::vector<double>(values.begin(), values.end()));
  }
  point_data& add(std::string name, const std::vector<double>& values) {
    return add(std::move(name), std::span<const double>(values));
  }
  point_data& add(std::string name, std::vector<double>&& values) {  // taken, not copied
    return add_values(std::move(name), 1, std::move(values));
  }
  // values  #points 2-vectors, written as 3 components with z = 0 so ParaView shows vectors
  point_data& add(std::string name, const std::vector<vec2>& values) {
    return add_values(std::move(name), 3, flat(values));
  }
  // values  #points 3x3 tensors, written row-major (xx xy xz yx yy yz zx zy zz) as VTK expects
  point_data& add(std::string name, const std::vector<mat3>& values) {
    return add_values(std::move(name), 9, flat(values));
  }

  // values  #points * components, point-major (the flat form of any of the above).
  point_data& add_values(std::string name, int components, std::vector<double> values) {
    check_name(name);
    arrays_.push_back(array{std::move(name), components, std::move(values)});
    return *this;
  }
  // values computed when written: produce() returns #points * components values, point-major.
  point_data& add_deferred(std::string name, int components, producer produce) {
    check_name(name);
    arrays_.push_back(array{std::move(name), components, {}, std::move(produce)});
    return *this;
  }

  // values made piecewise, `count` (#points * components) of them: prepare(), run when the writer
  // reaches the array, returns fill(first, n, out), and the writer asks for a chunk at a time, so
  // that a large array is never held whole (the runner's snapshots at 10^6 particles). Read
  // whole, produce() fills all of it.
  point_data& add_filled(std::string name, int components, std::size_t count, std::function<filler()> prepare) {
    check_name(name);
    producer whole = [count, prepare] { return filled_values(count, prepare); };
    arrays_.push_back(array{std::move(name), components, {}, std::move(whole), std::move(prepare)});
    return *this;
  }

  // The point-major form of the overloads above: #points 2-vectors as (x, y, 0), 3x3 tensors row-major.
  static std::vector<double> flat(const std::vector<vec2>& values) {
    std::vector<double> out;
    out.reserve(3 * values.size());
    for (const auto& v : values) out.insert(out.end(), {v.x(), v.y(), 0.0});
    return out;
  }
  static std::vector<double> flat(const std::vector<mat3>& values) {
    std::vector<double> out;
    out.reserve(9 * values.size());
    for (const auto& m : values)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out.push_back(m(r, c));
    return out;
  }

  const std::vector<array>& arrays() const { return arrays_; }
  bool empty() const { return arrays_.empty(); }
  // The arrays handed over, this left empty (for a caller that remakes them without a copy).
  std::vector<array> take() && { return std::move(arrays_); }

 private:
  void check_name(const std::string& name) const {
    if (name.empty()) fail("point_data: empty array name; give every array a name");
    for (const auto& a : arrays_)
      if (a.name == name) fail("point_data: array \"{}\" added twice; give each array a distinct name", name);
  }
  std::vector<array> arrays_;
};

// `data`, on n points, on n + source.size(): extra point j carries the values of point source[j]
// in every array, and each array stays given, deferred or filled as it was (the crack faces and
// failed points of a snapshot, io/crack_snapshot.hpp).
inline point_data with_extra_points(point_data data, std::size_t n, std::vector<index_t> source) {
  const auto extras = std::make_shared<const std::vector<index_t>>(std::move(source));
  const auto extend = [n, extras](std::vector<double>& values, std::size_t c) {
    values.resize((n + extras->size()) * c);
    for (std::size_t j = 0; j < extras->size(); ++j)
      std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>((*extras)[j]) * c), c,
                  values.begin() + static_cast<std::ptrdiff_t>((n + j) * c));
  };
  point_data out;
  for (point_data::array& a : std::move(data).take()) {
    const auto c = static_cast<std::size_t>(a.components);
    if (a.prepare) {
      out.add_filled(a.name, a.components, (n + extras->size()) * c, [prepare = a.prepare, n, c, extras] {
        return point_data::filler([fill = prepare(), n, c, extras](std::size_t first, std::size_t count, double* o) {
          const std::size_t own = first < n * c ? std::min(count, n * c - first) : 0;
          if (own > 0) fill(first, own, o);
          for (std::size_t k = own; k < count; ++k) {
            const std::size_t entry = first + k - n * c;
            fill(static_cast<std::size_t>((*extras)[entry / c]) * c + entry % c, 1, o + k);
          }
        });
      });
    } else if (a.produce) {
      out.add_deferred(a.name, a.components, [produce = a.produce, c, extend] {
        std::vector<double> values = produce();
        extend(values, c);
        return values;
      });
    } else {
      extend(a.values, c);
      out.add_values(a.name, a.components, std::move(a.values));
    }
  }
  return out;
}

}  // namespace rkpm::io
