#pragma once
// VTK XML output for ParaView (docs/method.md section 9.4): write_vtu() writes the particles of one
// snapshot as the points (z = 0) of an UnstructuredGrid with per-particle point arrays
// (displacement, velocity, stress, equivalent plastic strain, det F, ...) and cells on them:
// the background cells as VTK_QUADs when the particles are their nodes, so ParaView draws the
// deformed body as a surface coloured by any array, else a VTK_VERTEX per particle
// (io/vtu_cells.hpp); pvd_series keeps the .pvd index of a time series valid after every added
// snapshot (io/pvd_series.hpp).
//
// Arrays are Float64 so nothing is lost against the solver's doubles. Encodings, as VTK's own
// vtkXMLWriter writes them (header_type UInt64, native byte order):
//   appended (default)  every array's bytes in one raw <AppendedData> block after the XML,
//                       each DataArray naming its offset: the smallest and fastest file
//   binary              base64 inside each DataArray (plain-text XML, a third larger)
//   ascii               shortest round-trip decimal text
// Binary data is zlib-compressed (compressor="vtkZLibDataCompressor", blocks of 32 KiB compressed
// in parallel by the OpenMP threads, the same bytes whatever their number: io/vtu_blocks.hpp) by
// libdeflate when the header is compiled with RKPM_WITH_LIBDEFLATE and linked with libdeflate,
// else by zlib (RKPM_WITH_ZLIB, linked with zlib); the rkpm CMake target does either when it
// finds the library (libdeflate-dev, zlib1g-dev). Without both the writer is the same minus
// compression, and asking for vtu_compression::zlib is an error saying so. vtu_compression::lz4
// writes the same blocks with LZ4 (compressor="vtkLZ4DataCompressor", io/vtu_lz4.hpp: several
// times as fast, larger, read by ParaView 5.5 and later but not by meshio) when compiled with
// RKPM_WITH_LZ4 and linked with liblz4 (liblz4-dev).

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iterator>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/files.hpp>
#include <rkpm/io/point_data.hpp>
#include <rkpm/io/vtu_arrays.hpp>
#include <rkpm/io/vtu_cells.hpp>

namespace rkpm::io {

namespace detail {
// Throws unless `cells` is a valid <Cells> block on n points.
inline void check_cells(const std::filesystem::path& path, const vtu_cells& cells, std::size_t n) {
  if (cells.offsets.size() != cells.types.size())
    fail("write_vtu '{}': {} cell offsets for {} cell types; give one of each per cell", path.string(),
         cells.offsets.size(), cells.types.size());
  std::int64_t end = 0;
  for (const std::int64_t o : cells.offsets) {  // every cell has at least one point
    if (o <= end) fail("write_vtu '{}': cell offsets must increase (offset {} after {})", path.string(), o, end);
    end = o;
  }
  if (static_cast<std::size_t>(end) != cells.connectivity.size())
    fail("write_vtu '{}': the last cell offset is {}, the connectivity has {} entries", path.string(), end,
         cells.connectivity.size());
  for (const std::int64_t p : cells.connectivity)
    if (p < 0 || static_cast<std::size_t>(p) >= n)
      fail("write_vtu '{}': a cell refers to point {} of {}", path.string(), p, n);
}
}  // namespace detail

namespace detail {
// write_vtu's body: add_points(arrays) adds the "Points" array, add_cells(arrays) the <Cells>.
// `cells`: how many there are (checked by the caller).
template <class AddPoints, class AddCells>
void write_vtu_with(const std::filesystem::path& path, std::size_t n, std::size_t cells, const point_data& data,
                    const vtu_format& format, const point_data& field_arrays, AddPoints add_points,
                    AddCells add_cells) {
  const auto check_size = [&](const point_data::array& a, std::size_t size) {
    if (size != n * static_cast<std::size_t>(a.components))
      fail("write_vtu '{}': array \"{}\" has {} entries for {} points; give one per particle",
           path.string(), a.name, size / static_cast<std::size_t>(a.components), n);
  };
  for (const auto& a : data.arrays())
    if (!a.produce) check_size(a, a.values.size());
  std::string out;
  vtu_arrays arrays(out, format);
  if (arrays.format().compression == vtu_compression::zlib) {
    if (!vtu_deflater_available(format.deflater))
      fail("write_vtu '{}': zlib compression by {} asked for, but rkpm was compiled without it; install "
           "libdeflate-dev or zlib1g-dev and reconfigure, or use vtu_compression::none", path.string(),
           format.deflater == vtu_deflater::zlib ? "zlib" : "libdeflate");
    if (format.zlib_level < 1 || format.zlib_level > 9)
      fail("write_vtu '{}': zlib level {} must be 1 to 9", path.string(), format.zlib_level);
  }
  if (arrays.format().compression == vtu_compression::lz4 && !vtu_lz4_available)
    fail("write_vtu '{}': LZ4 compression asked for, but rkpm was compiled without it; install liblz4-dev and "
         "reconfigure, or use vtu_compression::zlib", path.string());
  const bool text = format.encoding == vtu_encoding::ascii;
  out.reserve(1024 + (text ? n * 64 * (3 + data.arrays().size()) : 0));
  fmt::format_to(std::back_inserter(out),
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" header_type=\"UInt64\"{}>\n"
                 "  <UnstructuredGrid>\n",
                 std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian",
                 arrays.format().compression == vtu_compression::none
                     ? std::string()
                     : fmt::format(" compressor=\"{}\"", vtu_compressor_attribute(arrays.format().compression)));
  if (!field_arrays.empty()) {
    out += "    <FieldData>\n";
    for (const auto& a : field_arrays.arrays())
      if (!a.values.empty())
        arrays.add("Float64", a.name, a.components, std::span<const double>(a.values),
                   a.values.size() / static_cast<std::size_t>(a.components));
    out += "    </FieldData>\n";
  }
  fmt::format_to(std::back_inserter(out), "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n, cells);

  out += "      <PointData>\n";
  // A deferred array is made when its block is written (appended) or now, and let go once encoded.
  for (const auto& a : data.arrays()) {
    if (!a.produce) {
      arrays.add("Float64", a.name, a.components, std::span<const double>(a.values));
      continue;
    }
    if (a.prepare) {
      arrays.add_filled<double>("Float64", a.name, a.components, n * static_cast<std::size_t>(a.components),
                                a.prepare);
      continue;
    }
    arrays.add_produced(a.name, a.components, [&a, &check_size] {
      std::vector<double> values = a.produce();
      check_size(a, values.size());
      return values;
    });
  }
  out += "      </PointData>\n";
  out += "      <Points>\n";
  add_points(arrays);
  out += "      </Points>\n";

  out += "      <Cells>\n";
  add_cells(arrays);
  out += "      </Cells>\n"
         "    </Piece>\n"
         "  </UnstructuredGrid>\n";
  replace_file_with(path, [&](std::ostream& file) { arrays.write(file, "</VTKFile>\n"); });
}

// (x, y) -> (x, y, 0)
inline std::vector<double> points_xyz(const std::vector<vec2>& points) {
  std::vector<double> xyz(3 * points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    xyz[3 * i] = points[i].x();
    xyz[3 * i + 1] = points[i].y();
    xyz[3 * i + 2] = 0.0;
  }
  return xyz;
}
}  // namespace detail

// Writes one snapshot: points  #points particle positions (x, y) -> (x, y, 0); `cells` on them
// (io/vtu_cells.hpp: the background cells as quads, or a vertex per point); data arrays must
// have one entry per point; `field_arrays`, of any length, are the snapshot's <FieldData> (the
// runner's: each tool's vertices at the snapshot's time, "tool:NAME"). The file is replaced
// atomically.
inline void write_vtu(const std::filesystem::path& path, const std::vector<vec2>& points, const vtu_cells& cells,
                      const point_data& data, const vtu_format& format = {}, const point_data& field_arrays = {}) {
  detail::check_cells(path, cells, points.size());
  detail::write_vtu_with(
      path, points.size(), cells.size(), data, format, field_arrays,
      [&points](detail::vtu_arrays& a) { a.add_produced("Points", 3, [&points] { return detail::points_xyz(points); }); },
      [&cells](detail::vtu_arrays& a) {
        a.add("Int64", "connectivity", 1, std::span<const std::int64_t>(cells.connectivity));
        a.add("Int64", "offsets", 1, std::span<const std::int64_t>(cells.offsets));
        a.add("UInt8", "types", 1, std::span<const std::uint8_t>(cells.types));
      });
}

// The same with the positions and cells handed over: each of their arrays is let go once its
// block is written (the cells' and the points' come first in the file), so that a large snapshot
// does not hold them while its fields are written (at 10^6 particles 41 MB of cells and 16 MB of
// positions; the runner's snapshots).
inline void write_vtu(const std::filesystem::path& path, std::vector<vec2>&& points, vtu_cells&& cells,
                      const point_data& data, const vtu_format& format = {}, const point_data& field_arrays = {}) {
  detail::check_cells(path, cells, points.size());
  detail::write_vtu_with(
      path, points.size(), cells.size(), data, format, field_arrays,
      [&points](detail::vtu_arrays& a) {
        a.add_produced("Points", 3, [p = std::move(points)]() mutable {
          std::vector<double> xyz = detail::points_xyz(p);
          std::vector<vec2>().swap(p);
          return xyz;
        });
      },
      [&cells](detail::vtu_arrays& a) {
        a.add_taken("Int64", "connectivity", 1, std::move(cells.connectivity));
        a.add_taken("Int64", "offsets", 1, std::move(cells.offsets));
        a.add_taken("UInt8", "types", 1, std::move(cells.types));
      });
}

// The same with the points and cells made piecewise as they are written, so that a large
// snapshot holds neither (the runner's: 57 MB at 10^6 particles): xyz() returns fill(first, n,
// out) of the 3 * points coordinates (x, y, 0 per point), `cells` gives the cells entry by entry.
inline void write_vtu(const std::filesystem::path& path, std::size_t points, std::function<point_data::filler()> xyz,
                      const cell_layout& cells, const point_data& data, const vtu_format& format = {},
                      const point_data& field_arrays = {}) {
  // Each of the cells' arrays from its entry function.
  const auto entries = [&cells]<class T>(T (cell_layout::*entry)(std::size_t) const) {
    return [&cells, entry] {
      return value_filler<T>([&cells, entry](std::size_t first, std::size_t n, T* out) {
        for (std::size_t k = 0; k < n; ++k) out[k] = (cells.*entry)(first + k);
      });
    };
  };
  detail::write_vtu_with(
      path, points, cells.size(), data, format, field_arrays,
      [&](detail::vtu_arrays& a) { a.add_filled<double>("Float64", "Points", 3, 3 * points, std::move(xyz)); },
      [&](detail::vtu_arrays& a) {
        a.add_filled<std::int64_t>("Int64", "connectivity", 1, cells.connectivity_size(), entries(&cell_layout::connectivity));
        a.add_filled<std::int64_t>("Int64", "offsets", 1, cells.size(), entries(&cell_layout::offset));
        a.add_filled<std::uint8_t>("UInt8", "types", 1, cells.size(), entries(&cell_layout::type));
      });
}

// The same with every point a VTK_VERTEX cell.
inline void write_vtu(const std::filesystem::path& path, const std::vector<vec2>& points,
                      const point_data& data = {}, const vtu_format& format = {}) {
  write_vtu(path, points, vertex_cells(points.size()), data, format);
}

}  // namespace rkpm::io
