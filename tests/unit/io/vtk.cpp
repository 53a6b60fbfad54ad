// VTK XML output read back by an independent reader: meshio under /usr/bin/python3
// (Debian python3-meshio) checks coordinates, vertex cells and every array's shape and values,
// recomputed in Python from the same closed formulas, for every encoding (appended raw, inline
// base64, ascii), with and without zlib, and for a .pvd series; the background cells as quads
// (connectivity from the grid's formula, counter-clockwise: positive areas, tiling the grid),
// the rest as vertices, the tools in <FieldData>; check_vtu.py also walks the appended block's
// headers and zlib blocks itself (each block one whole zlib stream of its declared sizes, by
// libdeflate or zlib), and fails on a header that lies.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/io/field_figure.hpp>
#include <rkpm/io/pvd_series.hpp>
#include <rkpm/io/vtk.hpp>

#include "support/run_capture.hpp"
#include "support/vtu_formulas.hpp"

namespace test_unit_io_vtk {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

namespace fs = std::filesystem;
using rkpm::mat3;
using rkpm::vec2;

namespace {

const fs::path python = "/usr/bin/python3";

// Runs a command and returns its exit status and output (stdout and stderr).
using rkpm::test::run_capture;

// Runs check_vtu.py; meshio missing is a failure with the install command, never a skip.
void check_with_meshio(const std::string& args) {
  REQUIRE_MESSAGE(fs::exists(python), "/usr/bin/python3 missing: install python3-meshio (apt-get install python3-meshio)");
  const auto script = fs::path(__FILE__).parent_path() / "check_vtu.py";
  REQUIRE_MESSAGE(fs::exists(script), "helper script missing: " << script);
  const auto [rc, out] = run_capture(python.string() + " '" + script.string() + "' " + args);
  INFO("check_vtu.py " << args << "\n" << out);
  REQUIRE_MESSAGE(rc != 2, "meshio is not installed for /usr/bin/python3: install python3-meshio "
                           "(apt-get install python3-meshio)");
  CHECK(rc == 0);
}

// Runs check_vtu.py once on files it must each refuse ("PATH N ENCODING COMPRESSION", one
// per file), each with a message containing its `why`.
void check_vtu_refuses(const std::vector<std::pair<std::string, std::string>>& files_and_whys) {
  const auto script = fs::path(__FILE__).parent_path() / "check_vtu.py";
  std::string args;
  for (const auto& [file, why] : files_and_whys) args += " " + file;
  const auto [rc, out] = run_capture(python.string() + " '" + script.string() + "' refuses" + args);
  INFO("check_vtu.py refuses" << args << "\n" << out);
  CHECK(rc == 0);
  std::istringstream lines(out);
  std::vector<std::string> verdicts;
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with("refused ") || line.starts_with("accepted ")) verdicts.push_back(line);
  REQUIRE(verdicts.size() == files_and_whys.size());
  for (std::size_t k = 0; k < verdicts.size(); ++k) {
    const auto& [file, why] = files_and_whys[k];
    CAPTURE(file);
    CAPTURE(verdicts[k]);
    CHECK(verdicts[k].starts_with("refused "));
    CHECK(verdicts[k].find(why) != std::string::npos);
  }
}

// The same closed formulas as expected() in check_vtu.py.
using snapshot = rkpm::test::vtu_snapshot;
snapshot make(int n) { return rkpm::test::snapshot_of(n); }

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

fs::path vtk_scratch() {
  auto dir = fs::temp_directory_path() / ("rkpm_unit_io_vtk_" + std::to_string(::getpid()));
  return dir;
}

}  // namespace

using rkpm::io::vtu_compression;
using rkpm::io::vtu_deflater;
using rkpm::io::vtu_encoding;
using rkpm::io::vtu_format;

const char* name(vtu_encoding e) {
  return e == vtu_encoding::appended ? "appended" : e == vtu_encoding::binary ? "binary" : "ascii";
}
const char* name(vtu_compression c) { return rkpm::io::vtu_compression_name(c).data(); }
const char* name(vtu_deflater d) { return d == vtu_deflater::zlib ? "zlib" : "libdeflate"; }

// The compressions this build can write (the first test case checks that zlib and LZ4 are
// among them), uncompressed first unless `with_none` is false.
std::vector<vtu_compression> built_compressions(bool with_none = true) {
  std::vector<vtu_compression> out;
  if (with_none) out.push_back(vtu_compression::none);
  if (rkpm::io::vtu_zlib_available) out.push_back(vtu_compression::zlib);
  if (rkpm::io::vtu_lz4_available) out.push_back(vtu_compression::lz4);
  return out;
}

// The libraries this build writes zlib streams with: libdeflate (the default) first.
std::vector<vtu_deflater> deflaters() {
  std::vector<vtu_deflater> out;
  for (auto d : {vtu_deflater::libdeflate, vtu_deflater::zlib})
    if (rkpm::io::vtu_deflater_available(d)) out.push_back(d);
  return out;
}

TEST_CASE("vtu: this build compresses, with libdeflate (libdeflate-dev and zlib1g-dev are listed packages)") {
  // The runner's snapshots rely on it; a build that lost either library should say so here.
  CHECK(rkpm::io::vtu_zlib_available);
  CHECK(rkpm::io::vtu_libdeflate_available);
  CHECK(rkpm::io::vtu_zlib_library_available);
  CHECK(rkpm::io::default_vtu_compression == vtu_compression::zlib);
  CHECK(vtu_format{}.deflater == vtu_deflater::libdeflate);
  CHECK(vtu_format{}.encoding == vtu_encoding::appended);
  CHECK(rkpm::io::vtu_lz4_available);  // liblz4-dev is a listed package too
}

TEST_CASE("vtu: meshio reads points, vertex cells and scalar/vector/tensor arrays exactly") {
  const auto dir = vtk_scratch();
  const auto compressions = built_compressions();  // LZ4 files decoded by check_vtu.py itself
  std::string files;
  for (auto encoding : {vtu_encoding::appended, vtu_encoding::binary, vtu_encoding::ascii}) {
    for (auto compression : compressions) {
      for (auto deflater : compression == vtu_compression::zlib ? deflaters() : std::vector{vtu_deflater::zlib}) {
        // 1, 2, 3, 37: every base64 padding case; 4100: a tensor array of 295,200 bytes is ten
        // 32 KiB zlib blocks and a partial one.
        for (int n : {1, 2, 3, 37, 4100}) {
          const auto s = make(n);
          const auto path = dir / "one" / fmt::format("snap_{}_{}_{}_{}.vtu", name(encoding), name(compression),
                                                      name(deflater), n);
          vtu_format format(encoding, compression);
          format.deflater = deflater;
          rkpm::io::write_vtu(path, s.points, s.data, format);
          files += fmt::format(" '{}' {} {} {}", path.string(), n, name(encoding), name(compression));
        }
      }
    }
  }
  check_with_meshio("vtus" + files);  // one start of Python for every file
  fs::remove_all(dir);
}

// The grid of check_vtu.py's grid(): nx x ny nodes, point k = i + nx j at a sheared position,
// then `extra` points that no cell uses.
static std::vector<vec2> vtk_grid_points(int nx, int ny, int extra) {
  std::vector<vec2> x;
  for (int k = 0; k < nx * ny + extra; ++k) {
    const double i = k % nx, j = k / nx;
    x.emplace_back(i * 0.5 + 0.01 * j * j, j * 0.25 - 0.002 * i * i);
  }
  return x;
}

TEST_CASE("vtu: the background cells as counter-clockwise VTK quads on the particles, the rest vertices") {
  const auto dir = vtk_scratch() / "cells";
  std::string grids;
  for (const auto& [nx, ny, extra, level] : {std::array{2, 2, 0, 6}, std::array{7, 5, 3, 1}, std::array{40, 30, 1, 6}}) {
    CAPTURE(nx);
    CAPTURE(extra);
    // The cells of the solver's grid numbering (make_grid_mesh), on the sheared points.
    auto mesh = rkpm::make_grid_mesh(vec2(0.0, 0.0), vec2(1.0, 1.0), Eigen::Vector2i(nx, ny));
    const auto points = vtk_grid_points(nx, ny, extra);
    mesh.node.assign(points.begin(), points.begin() + nx * ny);
    const auto cells = rkpm::io::quad_cells(mesh, points.size());
    REQUIRE(cells.size() == static_cast<std::size_t>((nx - 1) * (ny - 1) + extra));
    rkpm::io::point_data data, tools;
    std::vector<double> eps;
    std::vector<vec2> u;
    for (std::size_t k = 0; k < points.size(); ++k) {
      eps.push_back(static_cast<double>(k) / 7.0 - 2.5);
      u.push_back(points[k] * 1e-3);
    }
    data.add("eps_p", eps).add("u", u);
    tools.add("tool:die", std::vector<vec2>{vec2(-1.0, -0.5), vec2(3.0, -0.5), vec2(3.5, 2.0)});
    vtu_format format;
    format.zlib_level = level;
    const auto path = dir / fmt::format("grid_{}_{}_{}.vtu", nx, ny, extra);
    rkpm::io::write_vtu(path, points, cells, data, format, tools);
    grids += fmt::format(" '{}' {} {} {}", path.string(), nx, ny, extra);
  }
  check_with_meshio("cells" + grids);  // one start of Python for every file
  // A cell on a point that does not exist is refused before anything is written.
  auto mesh = rkpm::make_grid_mesh(vec2(0.0, 0.0), vec2(1.0, 1.0), Eigen::Vector2i(3, 3));
  CHECK_THROWS_AS(rkpm::io::quad_cells(mesh, 8), rkpm::error);
  auto cells = rkpm::io::quad_cells(mesh, 9);
  cells.connectivity.back() = 9;
  CHECK_THROWS_AS(rkpm::io::write_vtu(dir / "bad.vtu", mesh.node, cells, {}), rkpm::error);
  CHECK_FALSE(fs::exists(dir / "bad.vtu"));
  fs::remove_all(dir);
}

TEST_CASE("vtu: the zlib and LZ4 blocks are compressed in parallel, the file the same bytes on 1 and 2 threads") {
  const auto dir = vtk_scratch() / "threads";
  // The tensor array: 5.04 MB, 154 blocks, more than one chunk of the appended writer
  // (vtu_blocks_per_chunk, 128), compressed and written in two pieces.
  const int n = 70000;
  REQUIRE(9 * sizeof(double) * n > rkpm::io::detail::vtu_blocks_per_chunk * rkpm::io::detail::vtu_block_size);
  const auto s = make(n);
  std::vector<vtu_format> formats;
  for (auto deflater : deflaters()) {
    formats.emplace_back();
    formats.back().deflater = deflater;
  }
  if (rkpm::io::vtu_lz4_available) formats.emplace_back(vtu_encoding::appended, vtu_compression::lz4);
  std::string files;
  for (const auto& format : formats) {
    const std::string label = format.compression == vtu_compression::lz4 ? "lz4" : name(format.deflater);
    CAPTURE(label);
    std::string bytes[2];
    for (int threads : {1, 2}) {
#ifdef _OPENMP
      omp_set_num_threads(threads);
#endif
      const auto path = dir / fmt::format("{}_t{}.vtu", label, threads);
      rkpm::io::write_vtu(path, s.points, s.data, format);
      std::ifstream in(path, std::ios::binary);
      bytes[threads - 1].assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
#ifdef _OPENMP
    omp_set_num_threads(omp_get_num_procs());
#endif
    CHECK(bytes[0].size() > 100000);
    CHECK(bytes[0] == bytes[1]);
    files += fmt::format(" '{}' {} appended {}", (dir / fmt::format("{}_t2.vtu", label)).string(), n,
                         name(format.compression));
  }
  check_with_meshio("vtus" + files);  // one start of Python for every file
  fs::remove_all(dir);
}

TEST_CASE("vtu: check_vtu.py refuses a compression header that lies about its blocks") {
  // The check that the blocks are right must be able to fail: the header of the array at offset 0
  // of the appended block ([#blocks, block size, last block, compressed sizes]) altered one entry
  // at a time, the zlib streams (LZ4 blocks) left as they are.
  const auto dir = vtk_scratch() / "lies";
  const auto s = make(20000);
  std::string good_files;
  std::vector<std::pair<std::string, std::string>> lies;
  for (auto compression : built_compressions(false)) {
    const std::string kind = name(compression);
    const auto good = dir / (kind + "_good.vtu");
    rkpm::io::write_vtu(good, s.points, s.data, vtu_format(vtu_encoding::appended, compression));
    good_files += fmt::format(" '{}' 20000 appended {}", good.string(), kind);
    const std::string bytes = file_bytes(good);
    const std::string mark = "<AppendedData encoding=\"raw\">\n   _";
    const auto at = bytes.find(mark);
    REQUIRE(at != std::string::npos);
    const std::size_t header = at + mark.size();
    auto lie = [&](const std::string& file, int entry, std::int64_t change, const std::string& why) {
      std::string bad = bytes;
      std::uint64_t v;
      std::memcpy(&v, bad.data() + header + 8 * entry, 8);
      v += static_cast<std::uint64_t>(change);
      std::memcpy(bad.data() + header + 8 * entry, &v, 8);
      const auto path = dir / (kind + "_" + file);
      std::ofstream(path, std::ios::binary) << bad;
      lies.emplace_back(fmt::format("'{}' 20000 appended {}", path.string(), kind), why);
    };
    lie("block_size.vtu", 1, -16384, "block size 16384");
    lie("last_block.vtu", 2, 1, "last block");
    if (compression == vtu_compression::zlib) {
      lie("short_stream.vtu", 3, -1, "does not end in its");
      lie("long_stream.vtu", 3, 1, "ends 1 bytes before");
    } else {
      lie("short_block.vtu", 3, -1, "is not an LZ4 block");
      lie("long_block.vtu", 3, 1, "is not an LZ4 block");
    }
  }
  check_with_meshio("vtus" + good_files);  // the files the lies were made from pass
  check_vtu_refuses(lies);
  fs::remove_all(dir);
}

TEST_CASE("vtu: appended raw is smaller than base64, zlib smaller still, ascii largest") {
  const auto dir = vtk_scratch() / "sizes";
  const auto s = make(4100);
  auto size = [&](vtu_format f) {
    const auto path = dir / fmt::format("{}_{}.vtu", name(f.encoding), name(f.compression));
    rkpm::io::write_vtu(path, s.points, s.data, f);
    return fs::file_size(path);
  };
  const auto appended = size({vtu_encoding::appended, vtu_compression::none});
  const auto base64 = size({vtu_encoding::binary, vtu_compression::none});
  const auto ascii = size({vtu_encoding::ascii, vtu_compression::none});
  // 4100 points of 17 doubles (14 in the arrays, 3 coordinates), 2 Int64 and a UInt8.
  const std::uintmax_t values = 4100 * (17 * 8 + 2 * 8 + 1);
  CHECK(appended > values);
  CHECK(appended < values + 4096);  // headers and XML only
  CHECK(base64 > values * 4 / 3);
  CHECK(base64 < values * 4 / 3 + 4096);
  CHECK(ascii > base64);
  if (rkpm::io::vtu_zlib_available) {
    const auto zlib = size({vtu_encoding::appended, vtu_compression::zlib});
    CHECK(zlib < appended / 2);  // the vertex cells and zero z components compress to almost nothing
    // The default is level 1 (io/vtu_encoding.hpp says why); zlib's default, 6, is no larger.
    CHECK(vtu_format{}.zlib_level == 1);
    vtu_format level6{vtu_encoding::appended, vtu_compression::zlib};
    level6.zlib_level = 6;
    CHECK(size(level6) <= zlib);
    level6.zlib_level = 0;
    CHECK_THROWS_AS(rkpm::io::write_vtu(dir / "bad.vtu", s.points, s.data, level6), rkpm::error);
    if (rkpm::io::vtu_lz4_available) {
      // LZ4 finds the same zero runs and repeats, less tightly (here about 0.51 of raw).
      const auto lz4 = size({vtu_encoding::appended, vtu_compression::lz4});
      CHECK(lz4 < appended * 3 / 4);
      CHECK(lz4 > zlib);
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("vtu: an array of the wrong length is refused, naming the array") {
  const auto s = make(4);
  rkpm::io::point_data bad;
  bad.add("pressure", std::vector<double>(3, 1.0));
  try {
    rkpm::io::write_vtu(vtk_scratch() / "bad.vtu", s.points, bad);
    FAIL("no exception");
  } catch (const rkpm::error& e) {
    CHECK(std::string(e.what()).find("pressure") != std::string::npos);
  }
  CHECK_FALSE(fs::exists(vtk_scratch() / "bad.vtu"));
  rkpm::io::point_data twice;
  twice.add("a", std::vector<double>(4, 0.0));
  CHECK_THROWS_AS(twice.add("a", std::vector<double>(4, 0.0)), rkpm::error);
}

TEST_CASE("vtu: deferred arrays write the same bytes as the arrays given, each computed once when written") {
  const auto dir = vtk_scratch() / "deferred";
  const auto s = make(1500);
  // The same arrays, each produced by a call that counts itself.
  int calls = 0;
  rkpm::io::point_data deferred;
  for (const auto& a : s.data.arrays())
    deferred.add_deferred(a.name, a.components, [&calls, values = a.values] {
      ++calls;
      return values;
    });
  for (const auto& a : deferred.arrays()) CHECK(a.values.empty());  // nothing computed yet
  const auto compressions = built_compressions();
  for (auto e : {vtu_encoding::appended, vtu_encoding::binary, vtu_encoding::ascii})
    for (auto c : compressions) {
      CAPTURE(name(e));
      CAPTURE(name(c));
      const vtu_format f{e, c};
      rkpm::io::write_vtu(dir / "given.vtu", s.points, s.data, f);
      calls = 0;
      rkpm::io::write_vtu(dir / "deferred.vtu", s.points, deferred, f);
      CHECK(calls == static_cast<int>(s.data.arrays().size()));
      CHECK(file_bytes(dir / "given.vtu") == file_bytes(dir / "deferred.vtu"));
    }
  // A deferred array of the wrong length is refused by name when it is computed, and no file is left.
  rkpm::io::point_data bad;
  bad.add_deferred("temperature_K", 1, [] { return std::vector<double>(7, 294.0); });
  try {
    rkpm::io::write_vtu(dir / "bad.vtu", s.points, bad);
    FAIL("no exception");
  } catch (const rkpm::error& e) {
    CHECK(std::string(e.what()).find("temperature_K") != std::string::npos);
  }
  CHECK_FALSE(fs::exists(dir / "bad.vtu"));
  CHECK_THROWS_AS(bad.add_deferred("temperature_K", 1, [] { return std::vector<double>(); }), rkpm::error);
  fs::remove_all(dir);
}

TEST_CASE("vtu: positions and cells handed over write the same bytes and are let go") {
  // write_vtu(path, std::move(points), std::move(cells), ...) frees each array once its block is
  // written; the file is the one the const& form writes, in every encoding and compression.
  const auto dir = vtk_scratch() / "handed";
  const int nx = 30, ny = 20;
  auto mesh = rkpm::make_grid_mesh(vec2(0.0, 0.0), vec2(1.0, 1.0), Eigen::Vector2i(nx, ny));
  const auto points = vtk_grid_points(nx, ny, 2);
  mesh.node.assign(points.begin(), points.begin() + nx * ny);
  const auto cells = rkpm::io::quad_cells(mesh, points.size());
  rkpm::io::point_data data;
  std::vector<double> eps;
  for (std::size_t k = 0; k < points.size(); ++k) eps.push_back(static_cast<double>(k) / 7.0 - 2.5);
  data.add("eps_p", eps);
  const auto compressions = built_compressions();
  for (auto e : {vtu_encoding::appended, vtu_encoding::binary, vtu_encoding::ascii})
    for (auto c : compressions) {
      CAPTURE(name(e));
      CAPTURE(name(c));
      const vtu_format f{e, c};
      rkpm::io::write_vtu(dir / "kept.vtu", points, cells, data, f);
      auto p = points;
      auto k = cells;
      rkpm::io::write_vtu(dir / "handed.vtu", std::move(p), std::move(k), data, f);
      CHECK(p.empty());  // taken by the writer, not copied (a moved-from vector is empty)
      CHECK((k.connectivity.empty() && k.offsets.empty() && k.types.empty()));
      CHECK(file_bytes(dir / "kept.vtu") == file_bytes(dir / "handed.vtu"));
    }
  // The same through a series (the runner's call), in the default format.
  rkpm::io::write_vtu(dir / "kept.vtu", points, cells, data);
  rkpm::io::pvd_series pvd(dir / "run.pvd");
  auto p = points;
  auto k = cells;
  const auto vtu = pvd.add_snapshot(0.0, std::move(p), std::move(k), data);
  CHECK(file_bytes(vtu) == file_bytes(dir / "kept.vtu"));
  fs::remove_all(dir);
}

TEST_CASE("vtu: points, cells and arrays made piecewise write the bytes of the whole arrays") {
  // write_vtu(path, n, xyz, cell_layout, ...) and point_data::add_filled make their arrays a
  // chunk of 4 MiB at a time (the runner's snapshots); the file is the one the whole arrays give,
  // in every encoding and compression. 420 x 420 nodes (appended): the points' and the
  // connectivity's bytes span two chunks, which end inside a point's row; two points no quad uses
  // are vertex cells.
  const auto dir = vtk_scratch() / "filled";
  for (const int nx : {420, 9}) {
    const int ny = nx;
    auto mesh = rkpm::make_grid_mesh(vec2(0.0, 0.0), vec2(1.0, 1.0), Eigen::Vector2i(nx, ny));
    const auto points = vtk_grid_points(nx, ny, 2);
    mesh.node.assign(points.begin(), points.begin() + nx * ny);
    const std::size_t n = points.size();
    std::vector<double> eps;
    for (std::size_t k = 0; k < n; ++k) eps.push_back(static_cast<double>(k) / 7.0 - 2.5);
    rkpm::io::point_data whole, filled;
    whole.add("eps_p", eps);
    filled.add_filled("eps_p", 1, n, [&eps] {
      return rkpm::io::point_data::filler(
          [&eps](std::size_t first, std::size_t count, double* out) { std::copy_n(eps.data() + first, count, out); });
    });
    CHECK(filled.arrays()[0].produce() == eps);  // read whole
    const auto xyz = [&points] {
      return rkpm::io::point_data::filler([&points](std::size_t first, std::size_t count, double* out) {
        for (std::size_t k = first; k < first + count; ++k) out[k - first] = k % 3 < 2 ? points[k / 3][k % 3] : 0.0;
      });
    };
    for (const bool quads : {true, false}) {
      const auto cells = quads ? rkpm::io::quad_cells(mesh, n) : rkpm::io::vertex_cells(n);
      const auto layout = quads ? rkpm::io::cell_layout::quads(mesh, n) : rkpm::io::cell_layout::vertices(n);
      CHECK(layout.size() == cells.size());
      for (auto e : {vtu_encoding::appended, vtu_encoding::binary, vtu_encoding::ascii}) {
        if (e != vtu_encoding::appended && nx > 9) continue;  // only appended arrays are chunked
        for (auto c : built_compressions()) {
          CAPTURE(nx);
          CAPTURE(quads);
          CAPTURE(name(e));
          CAPTURE(name(c));
          const vtu_format f{e, c};
          rkpm::io::write_vtu(dir / "whole.vtu", points, cells, whole, f);
          rkpm::io::write_vtu(dir / "filled.vtu", n, xyz, layout, filled, f);
          CHECK(file_bytes(dir / "whole.vtu") == file_bytes(dir / "filled.vtu"));
        }
      }
      if (nx > 9) continue;
      // A field figure reads either form of the cells alike (the runner's draws from the layout).
      rkpm::io::field_png(dir / "arrays.png", points, cells, eps, {}, {.title = "cells", .label = "eps"});
      rkpm::io::field_png(dir / "layout.png", points, layout, eps, {}, {.title = "cells", .label = "eps"});
      CHECK(file_bytes(dir / "arrays.png").size() > 1000);
      CHECK(file_bytes(dir / "arrays.png") == file_bytes(dir / "layout.png"));
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("pvd: the index is valid after every addition and lists each added file") {
  const auto dir = vtk_scratch() / "series";
  rkpm::io::pvd_series pvd(dir / "run.pvd");
  // The index as it stands after each addition, copied beside it (its file names are relative
  // to its directory) and checked in one start of Python at the end.
  std::string indexes;
  auto keep_index = [&](int k, const std::string& expect) {
    const auto copy = dir / fmt::format("index_{}.pvd", k);
    fs::copy_file(pvd.path(), copy, fs::copy_options::overwrite_existing);
    indexes += fmt::format("{}'{}'{}", indexes.empty() ? "" : " / ", copy.string(), expect);
  };
  keep_index(0, "");  // a valid (empty) collection before any snapshot

  const double times[] = {0.0, 1e-6, 2.5e-6};
  const int sizes[] = {5, 8, 13};
  std::string expect;
  for (int k = 0; k < 3; ++k) {
    const auto s = make(sizes[k]);
    const auto vtu = pvd.add_snapshot(times[k], s.points, s.data);  // default: appended, zlib
    CHECK(vtu.parent_path() == dir);
    CHECK(vtu.filename() == fmt::format("run_{:06d}.vtu", k));
    expect += fmt::format(" {},{}", times[k], sizes[k]);
    keep_index(k + 1, expect);  // as if the run died right here: the snapshots so far
  }
  // add() with a caller-written file, named relative to the .pvd directory.
  const auto s = make(3);
  fs::create_directories(dir / "extra");
  rkpm::io::write_vtu(dir / "extra" / "late.vtu", s.points, s.data, vtu_encoding::ascii);
  pvd.add(4e-6, "extra/late.vtu");
  CHECK(pvd.size() == 4);
  indexes += fmt::format(" / '{}'{} 4e-06,3", pvd.path().string(), expect);
  check_with_meshio("pvd " + indexes);
  CHECK_FALSE(fs::exists(dir / "run.pvd.tmp"));
  fs::remove_all(vtk_scratch());
}

}  // namespace test_unit_io_vtk
