#pragma once
// VTK XML output for ParaView (docs/method.md section 9.4): write_vtu() writes the particles of one
// snapshot as an UnstructuredGrid of VTK_VERTEX cells (z = 0) with per-particle arrays
// (displacement, velocity, stress, equivalent plastic strain, det F, ...); pvd_series keeps the
// .pvd index of a time series valid after every added snapshot.
//
// Arrays are Float64 so nothing is lost against the solver's doubles. The default encoding is
// inline base64 ("binary"): one base64 stream holding a UInt64 byte count followed by the raw
// little-/big-endian values, as VTK's own vtkXMLWriter writes it uncompressed; "ascii" writes
// shortest round-trip decimal text instead.

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/files.hpp>

namespace rkpm::io {

enum class vtu_encoding { binary, ascii };

// Named per-particle arrays of one snapshot, in the order they were added (ParaView lists them
// in that order). Values are copied: a snapshot is written once, not every step.
class point_data {
 public:
  struct array {
    std::string name;
    int components;              // 1 scalar, 3 vector (2D + zero z), 9 tensor (row-major)
    std::vector<double> values;  // #points * components, point-major
  };

  // values  #points scalars
  point_data& add(std::string name, std::span<const double> values) {
    return add_flat(std::move(name), 1, std::vector<double>(values.begin(), values.end()));
  }
  point_data& add(std::string name, const std::vector<double>& values) {
    return add(std::move(name), std::span<const double>(values));
  }
  // values  #points 2-vectors, written as 3 components with z = 0 so ParaView shows vectors
  point_data& add(std::string name, const std::vector<vec2>& values) {
    std::vector<double> flat;
    flat.reserve(3 * values.size());
    for (const auto& v : values) flat.insert(flat.end(), {v.x(), v.y(), 0.0});
    return add_flat(std::move(name), 3, std::move(flat));
  }
  // values  #points 3x3 tensors, written row-major (xx xy xz yx yy yz zx zy zz) as VTK expects
  point_data& add(std::string name, const std::vector<mat3>& values) {
    std::vector<double> flat;
    flat.reserve(9 * values.size());
    for (const auto& m : values)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) flat.push_back(m(r, c));
    return add_flat(std::move(name), 9, std::move(flat));
  }

  const std::vector<array>& arrays() const { return arrays_; }
  bool empty() const { return arrays_.empty(); }

 private:
  point_data& add_flat(std::string name, int components, std::vector<double> flat) {
    if (name.empty()) fail("point_data: empty array name; give every array a name");
    for (const auto& a : arrays_)
      if (a.name == name) fail("point_data: array \"{}\" added twice; give each array a distinct name", name);
    arrays_.push_back(array{std::move(name), components, std::move(flat)});
    return *this;
  }
  std::vector<array> arrays_;
};

namespace detail {

inline std::string xml_escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

inline void append_base64(std::string& out, const unsigned char* bytes, std::size_t n) {
  static constexpr char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::size_t i = 0;
  for (; i + 3 <= n; i += 3) {
    const std::uint32_t w = (std::uint32_t{bytes[i]} << 16) | (std::uint32_t{bytes[i + 1]} << 8) | bytes[i + 2];
    out += table[(w >> 18) & 63];
    out += table[(w >> 12) & 63];
    out += table[(w >> 6) & 63];
    out += table[w & 63];
  }
  if (const std::size_t rest = n - i; rest > 0) {
    std::uint32_t w = std::uint32_t{bytes[i]} << 16;
    if (rest == 2) w |= std::uint32_t{bytes[i + 1]} << 8;
    out += table[(w >> 18) & 63];
    out += table[(w >> 12) & 63];
    out += rest == 2 ? table[(w >> 6) & 63] : '=';
    out += '=';
  }
}

// One DataArray body: header (UInt64 byte count) and values in one base64 stream, or text.
template <class T>
void append_values(std::string& out, std::span<const T> values, vtu_encoding encoding) {
  if (encoding == vtu_encoding::ascii) {
    for (std::size_t i = 0; i < values.size(); ++i) {
      out += (i % 9 == 0) ? "\n          " : " ";
      fmt::format_to(std::back_inserter(out), "{}", values[i]);
    }
    out += "\n        ";
    return;
  }
  const std::uint64_t bytes = values.size() * sizeof(T);
  std::vector<unsigned char> raw(sizeof(std::uint64_t) + bytes);
  std::memcpy(raw.data(), &bytes, sizeof bytes);
  if (bytes) std::memcpy(raw.data() + sizeof bytes, values.data(), bytes);
  out += "\n          ";
  append_base64(out, raw.data(), raw.size());
  out += "\n        ";
}

template <class T>
void append_data_array(std::string& out, std::string_view type, std::string_view name, int components,
                       std::span<const T> values, vtu_encoding encoding) {
  fmt::format_to(std::back_inserter(out), "        <DataArray type=\"{}\"", type);
  if (!name.empty()) fmt::format_to(std::back_inserter(out), " Name=\"{}\"", xml_escape(name));
  if (components > 1) fmt::format_to(std::back_inserter(out), " NumberOfComponents=\"{}\"", components);
  fmt::format_to(std::back_inserter(out), " format=\"{}\">",
                 encoding == vtu_encoding::ascii ? "ascii" : "binary");
  append_values(out, values, encoding);
  out += "</DataArray>\n";
}

}  // namespace detail

// Writes one snapshot: points  #points particle positions (x, y) -> (x, y, 0), each a
// VTK_VERTEX cell; data arrays must have one entry per point. The file is replaced atomically.
inline void write_vtu(const std::filesystem::path& path, const std::vector<vec2>& points,
                      const point_data& data = {}, vtu_encoding encoding = vtu_encoding::binary) {
  const std::size_t n = points.size();
  for (const auto& a : data.arrays())
    if (a.values.size() != n * static_cast<std::size_t>(a.components))
      fail("write_vtu '{}': array \"{}\" has {} entries for {} points; give one per particle",
           path.string(), a.name, a.values.size() / static_cast<std::size_t>(a.components), n);

  std::string out;
  out.reserve(256 + n * 64 * (3 + data.arrays().size()));
  fmt::format_to(std::back_inserter(out),
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" header_type=\"UInt64\">\n"
                 "  <UnstructuredGrid>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                 std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian", n, n);

  out += "      <PointData>\n";
  for (const auto& a : data.arrays())
    detail::append_data_array(out, "Float64", a.name, a.components, std::span<const double>(a.values),
                              encoding);
  out += "      </PointData>\n";

  std::vector<double> xyz;
  xyz.reserve(3 * n);
  for (const auto& p : points) xyz.insert(xyz.end(), {p.x(), p.y(), 0.0});
  out += "      <Points>\n";
  detail::append_data_array(out, "Float64", "Points", 3, std::span<const double>(xyz), encoding);
  out += "      </Points>\n";

  // Cell I is the single vertex I: connectivity = offsets - 1 = 0..n-1, type 1 (VTK_VERTEX).
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t i = 0; i < n; ++i) {
    connectivity[i] = static_cast<std::int64_t>(i);
    offsets[i] = static_cast<std::int64_t>(i + 1);
  }
  const std::vector<std::uint8_t> types(n, std::uint8_t{1});
  out += "      <Cells>\n";
  detail::append_data_array(out, "Int64", "connectivity", 1, std::span<const std::int64_t>(connectivity),
                            encoding);
  detail::append_data_array(out, "Int64", "offsets", 1, std::span<const std::int64_t>(offsets), encoding);
  if (encoding == vtu_encoding::ascii) {
    // uint8 would print as characters through fmt's char-like handling; widen for text.
    const std::vector<int> types_text(n, 1);
    detail::append_data_array(out, "UInt8", "types", 1, std::span<const int>(types_text), encoding);
  } else {
    detail::append_data_array(out, "UInt8", "types", 1, std::span<const std::uint8_t>(types), encoding);
  }
  out += "      </Cells>\n"
         "    </Piece>\n"
         "  </UnstructuredGrid>\n"
         "</VTKFile>\n";
  replace_file(path, out);
}

// A .pvd collection: one DataSet per snapshot with its time, files given relative to the
// .pvd's directory. Every add() rewrites the whole index atomically, so a run that dies after
// any number of snapshots leaves a valid .pvd listing exactly those snapshots.
class pvd_series {
 public:
  explicit pvd_series(std::filesystem::path pvd_path) : path_(std::move(pvd_path)) { write(); }

  void add(double time, const std::string& vtu_filename_relative) {
    entries_.emplace_back(time, vtu_filename_relative);
    write();
  }

  // Writes <pvd stem>_<index, 6 digits>.vtu next to the .pvd and adds it; returns its path.
  std::filesystem::path add_snapshot(double time, const std::vector<vec2>& points, const point_data& data,
                                     vtu_encoding encoding = vtu_encoding::binary) {
    const std::string name = fmt::format("{}_{:06d}.vtu", path_.stem().string(), entries_.size());
    const auto vtu = path_.parent_path() / name;
    write_vtu(vtu, points, data, encoding);
    add(time, name);
    return vtu;
  }

  const std::filesystem::path& path() const { return path_; }
  std::size_t size() const { return entries_.size(); }

 private:
  void write() const {
    std::string out =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"Collection\" version=\"0.1\">\n"
        "  <Collection>\n";
    for (const auto& [t, file] : entries_)
      fmt::format_to(std::back_inserter(out),
                     "    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t,
                     detail::xml_escape(file));
    out += "  </Collection>\n</VTKFile>\n";
    replace_file(path_, out);
  }

  std::filesystem::path path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace rkpm::io
