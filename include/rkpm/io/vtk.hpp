#pragma once
// VTK XML output for ParaView (docs/method.md section 9.4): write_vtu() writes the particles of one
// snapshot as an UnstructuredGrid of VTK_VERTEX cells (z = 0) with per-particle arrays
// (displacement, velocity, stress, equivalent plastic strain, det F, ...); pvd_series keeps the
// .pvd index of a time series valid after every added snapshot.
//
// Arrays are Float64 so nothing is lost against the solver's doubles. Encodings, as VTK's own
// vtkXMLWriter writes them (header_type UInt64, native byte order):
//   appended (default)  every array's bytes in one raw <AppendedData> block after the XML,
//                       each DataArray naming its offset: the smallest and fastest file
//   binary              base64 inside each DataArray (plain-text XML, a third larger)
//   ascii               shortest round-trip decimal text
// Binary data is zlib-compressed (compressor="vtkZLibDataCompressor", blocks of 32 KiB) when
// the header is compiled with RKPM_WITH_ZLIB and linked with zlib, which the rkpm CMake target
// does when find_package(ZLIB) finds it; without it the writer is the same minus compression,
// and asking for vtu_compression::zlib is an error saying so.

#include <algorithm>
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

#ifdef RKPM_WITH_ZLIB
#include <zlib.h>
#endif

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/files.hpp>

namespace rkpm::io {

enum class vtu_encoding { appended, binary, ascii };
enum class vtu_compression { none, zlib };

// True if this translation unit can compress (compiled with RKPM_WITH_ZLIB, linked with zlib).
#ifdef RKPM_WITH_ZLIB
inline constexpr bool vtu_zlib_available = true;
#else
inline constexpr bool vtu_zlib_available = false;
#endif
inline constexpr vtu_compression default_vtu_compression =
    vtu_zlib_available ? vtu_compression::zlib : vtu_compression::none;

// How a .vtu is written; converts from a bare encoding, so write_vtu(path, x, d,
// vtu_encoding::ascii) still reads as before. Compression applies to appended and binary data.
struct vtu_format {
  vtu_encoding encoding = vtu_encoding::appended;
  vtu_compression compression = default_vtu_compression;
  int zlib_level = 6;  // 1 (fastest) .. 9 (smallest); zlib's default is 6

  vtu_format() = default;
  vtu_format(vtu_encoding e, vtu_compression c = default_vtu_compression) : encoding(e), compression(c) {}  // NOLINT
};

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

// Bytes of one binary DataArray as VTK reads them: uncompressed, a UInt64 byte count then the
// values; compressed, the UInt64 header [#blocks, block size, size of a partial last block (0 if
// none), compressed size of each block] then the zlib streams of the 32 KiB blocks.
struct binary_block {
  std::vector<unsigned char> header, body;
};

inline constexpr std::size_t vtu_block_size = 32768;

inline void append_u64(std::vector<unsigned char>& out, std::uint64_t v) {
  unsigned char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  out.insert(out.end(), b, b + sizeof v);
}

inline binary_block encode_binary(const unsigned char* bytes, std::size_t size, const vtu_format& format,
                                  std::string_view name) {
  binary_block block;
  if (format.compression == vtu_compression::none) {
    append_u64(block.header, size);
    block.body.assign(bytes, bytes + size);
    return block;
  }
#ifdef RKPM_WITH_ZLIB
  const std::size_t blocks = (size + vtu_block_size - 1) / vtu_block_size;
  append_u64(block.header, blocks);
  append_u64(block.header, vtu_block_size);
  append_u64(block.header, size % vtu_block_size);
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t begin = b * vtu_block_size, n = std::min(vtu_block_size, size - begin);
    uLongf compressed = compressBound(static_cast<uLong>(n));
    const std::size_t at = block.body.size();
    block.body.resize(at + compressed);
    const int rc = compress2(block.body.data() + at, &compressed, bytes + begin, static_cast<uLong>(n),
                             format.zlib_level);
    if (rc != Z_OK) fail("write_vtu: zlib failed ({}) on array \"{}\"; try vtu_compression::none", rc, name);
    block.body.resize(at + compressed);
    append_u64(block.header, compressed);
  }
  return block;
#else
  fail("write_vtu: array \"{}\": zlib compression asked for, but rkpm was compiled without zlib; "
       "install zlib (Debian zlib1g-dev), compile with -DRKPM_WITH_ZLIB and link -lz, or use "
       "vtu_compression::none", name);
#endif
}

// Writes the XML of the DataArrays and collects the appended block: one object per file.
class vtu_arrays {
 public:
  vtu_arrays(std::string& xml, const vtu_format& format) : xml_(xml), format_(format) {
    if (format_.encoding == vtu_encoding::ascii) format_.compression = vtu_compression::none;
  }

  template <class T>
  void add(std::string_view type, std::string_view name, int components, std::span<const T> values) {
    fmt::format_to(std::back_inserter(xml_), "        <DataArray type=\"{}\"", type);
    if (!name.empty()) fmt::format_to(std::back_inserter(xml_), " Name=\"{}\"", xml_escape(name));
    if (components > 1) fmt::format_to(std::back_inserter(xml_), " NumberOfComponents=\"{}\"", components);
    switch (format_.encoding) {
      case vtu_encoding::ascii:
        xml_ += " format=\"ascii\">";
        for (std::size_t i = 0; i < values.size(); ++i) {
          xml_ += (i % 9 == 0) ? "\n          " : " ";
          // uint8 would print as a character through fmt's char-like handling; widen it.
          if constexpr (sizeof(T) == 1)
            fmt::format_to(std::back_inserter(xml_), "{}", static_cast<int>(values[i]));
          else
            fmt::format_to(std::back_inserter(xml_), "{}", values[i]);
        }
        xml_ += "\n        </DataArray>\n";
        return;
      case vtu_encoding::binary: {
        const auto block = encode(values, name);
        xml_ += " format=\"binary\">\n          ";
        if (format_.compression == vtu_compression::none) {
          // One base64 stream of count and values, as vtkXMLWriter writes it uncompressed.
          std::vector<unsigned char> all(block.header);
          all.insert(all.end(), block.body.begin(), block.body.end());
          append_base64(xml_, all.data(), all.size());
        } else {
          // Compressed: header and blocks are two base64 streams.
          append_base64(xml_, block.header.data(), block.header.size());
          append_base64(xml_, block.body.data(), block.body.size());
        }
        xml_ += "\n        </DataArray>\n";
        return;
      }
      case vtu_encoding::appended:
        blocks_.push_back(encode(values, name));
        xml_ += " format=\"appended\" offset=\"";
        marks_.push_back(xml_.size());  // the offset is written by finish()
        xml_ += "\"/>\n";
        return;
    }
  }

  // After the last array and the closing </UnstructuredGrid>: writes the offsets and the raw
  // <AppendedData> block. The arrays lie in it in reverse order of the XML. Any order is valid
  // VTK (each array is read at its offset); this one is also read right by meshio 7, whose raw
  // reader rewrites the offsets in place while looking arrays up by offset in document order,
  // so that in document order a rewritten offset of an earlier array can equal the raw offset of
  // a later one and shadow it.
  void finish() {
    if (format_.encoding != vtu_encoding::appended) return;
    std::vector<std::size_t> offset(blocks_.size());
    std::size_t bytes = 0;
    for (std::size_t k = blocks_.size(); k-- > 0;) {
      offset[k] = bytes;
      bytes += blocks_[k].header.size() + blocks_[k].body.size();
    }
    std::string out;
    out.reserve(xml_.size() + 24 * blocks_.size() + bytes + 64);
    std::size_t from = 0;
    for (std::size_t k = 0; k < blocks_.size(); ++k) {
      out.append(xml_, from, marks_[k] - from);
      fmt::format_to(std::back_inserter(out), "{}", offset[k]);
      from = marks_[k];
    }
    out.append(xml_, from);
    // "_" marks offset 0; the newline after the last byte is not data.
    out += "  <AppendedData encoding=\"raw\">\n   _";
    for (std::size_t k = blocks_.size(); k-- > 0;) {
      out.append(reinterpret_cast<const char*>(blocks_[k].header.data()), blocks_[k].header.size());
      out.append(reinterpret_cast<const char*>(blocks_[k].body.data()), blocks_[k].body.size());
    }
    out += "\n  </AppendedData>\n";
    xml_ = std::move(out);
  }

  const vtu_format& format() const { return format_; }

 private:
  template <class T>
  binary_block encode(std::span<const T> values, std::string_view name) const {
    return encode_binary(reinterpret_cast<const unsigned char*>(values.data()), values.size_bytes(), format_,
                         name);
  }

  std::string& xml_;
  vtu_format format_;
  std::vector<binary_block> blocks_;  // appended: each array's bytes, in XML order
  std::vector<std::size_t> marks_;    // appended: where each array's offset goes in xml_
};

}  // namespace detail

// Writes one snapshot: points  #points particle positions (x, y) -> (x, y, 0), each a
// VTK_VERTEX cell; data arrays must have one entry per point. The file is replaced atomically.
inline void write_vtu(const std::filesystem::path& path, const std::vector<vec2>& points,
                      const point_data& data = {}, const vtu_format& format = {}) {
  const std::size_t n = points.size();
  for (const auto& a : data.arrays())
    if (a.values.size() != n * static_cast<std::size_t>(a.components))
      fail("write_vtu '{}': array \"{}\" has {} entries for {} points; give one per particle",
           path.string(), a.name, a.values.size() / static_cast<std::size_t>(a.components), n);
  std::string out;
  detail::vtu_arrays arrays(out, format);
  if (arrays.format().compression == vtu_compression::zlib) {
    if (!vtu_zlib_available)
      fail("write_vtu '{}': zlib compression asked for, but rkpm was compiled without zlib; install "
           "zlib (Debian zlib1g-dev) and reconfigure, or use vtu_compression::none", path.string());
    if (format.zlib_level < 1 || format.zlib_level > 9)
      fail("write_vtu '{}': zlib level {} must be 1 to 9", path.string(), format.zlib_level);
  }
  const bool text = format.encoding == vtu_encoding::ascii;
  out.reserve(1024 + (text ? n * 64 * (3 + data.arrays().size()) : 0));
  fmt::format_to(std::back_inserter(out),
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" header_type=\"UInt64\"{}>\n"
                 "  <UnstructuredGrid>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                 std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian",
                 arrays.format().compression == vtu_compression::zlib ? " compressor=\"vtkZLibDataCompressor\"" : "",
                 n, n);

  out += "      <PointData>\n";
  for (const auto& a : data.arrays())
    arrays.add("Float64", a.name, a.components, std::span<const double>(a.values));
  out += "      </PointData>\n";

  std::vector<double> xyz;
  xyz.reserve(3 * n);
  for (const auto& p : points) xyz.insert(xyz.end(), {p.x(), p.y(), 0.0});
  out += "      <Points>\n";
  arrays.add("Float64", "Points", 3, std::span<const double>(xyz));
  out += "      </Points>\n";

  // Cell I is the single vertex I: connectivity = offsets - 1 = 0..n-1, type 1 (VTK_VERTEX).
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t i = 0; i < n; ++i) {
    connectivity[i] = static_cast<std::int64_t>(i);
    offsets[i] = static_cast<std::int64_t>(i + 1);
  }
  const std::vector<std::uint8_t> types(n, std::uint8_t{1});
  out += "      <Cells>\n";
  arrays.add("Int64", "connectivity", 1, std::span<const std::int64_t>(connectivity));
  arrays.add("Int64", "offsets", 1, std::span<const std::int64_t>(offsets));
  arrays.add("UInt8", "types", 1, std::span<const std::uint8_t>(types));
  out += "      </Cells>\n"
         "    </Piece>\n"
         "  </UnstructuredGrid>\n";
  arrays.finish();
  out += "</VTKFile>\n";
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
                                     const vtu_format& format = {}) {
    const std::string name = fmt::format("{}_{:06d}.vtu", path_.stem().string(), entries_.size());
    const auto vtu = path_.parent_path() / name;
    write_vtu(vtu, points, data, format);
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
