// rkpm_bench_vtu: the time to write one VTU snapshot (io/vtk.hpp) of about 10^6 particles, as
// the runner writes them (appended raw, zlib format, the background cells as quads), per OpenMP
// thread count, library and level (tools/rkpm bench --vtu [Google Benchmark options]).
//   BM_write_vtu/threads:T/libdeflate:D/level:L
//                      write_vtu on T threads, the zlib streams by libdeflate (D = 1) or zlib
//                      (D = 0) at level L, to a file in the temporary directory (the page cache:
//                      the disk is not timed); counters: file MB, particles. A library this
//                      build lacks is skipped with a message.
//   BM_write_vtu_lz4/threads:T
//                      the same with LZ4 (compressor="vtkLZ4DataCompressor", liblz4): the
//                      runner's --vtu-compression lz4
//   BM_write_vtu_uncompressed/threads:T
//                      the same without compression: what is not compression
// The fields are smooth functions of position with full-precision mantissas, as a solver's are
// (displacement, velocity, a plane stress tensor with zero out-of-plane shear, a plastic strain
// that is zero over half the body, det F), so that zlib sees data like a run's.
// The machine may be shared: compare the thread counts within one run.

#include <cmath>
#include <filesystem>
#include <vector>

#include <benchmark/benchmark.h>
#include <omp.h>

#include <rkpm/discretization/background_mesh.hpp>
#include <rkpm/io/vtk.hpp>

namespace {

using rkpm::mat3;
using rkpm::vec2;

struct snapshot {
  std::vector<vec2> points;
  rkpm::io::vtu_cells cells;
  rkpm::io::point_data data;
};

// side x side particles on a 10 mm square, its (side - 1)^2 cells as quads.
const snapshot& bench_snapshot(int side) {
  static snapshot s = [side] {
    snapshot out;
    const auto mesh = rkpm::make_grid_mesh(vec2(0.0, 0.0), vec2(0.01, 0.01), Eigen::Vector2i(side, side));
    out.cells = rkpm::io::quad_cells(mesh, mesh.node.size());
    const std::size_t n = mesh.node.size();
    std::vector<vec2> u(n), v(n);
    std::vector<mat3> sigma(n);
    std::vector<double> eps(n), det(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = mesh.node[i][0] * 300.0, y = mesh.node[i][1] * 300.0;
      u[i] = vec2(1e-4 * std::sin(x) * std::cos(0.7 * y), -2e-4 * std::cos(0.3 * x + y));
      v[i] = vec2(3.0 * std::cos(x + 0.2 * y), -227.0 + 5.0 * std::sin(y));
      const double sxx = 3e8 * std::sin(0.5 * x + y), syy = -2e8 * std::cos(x - 0.4 * y), sxy = 5e7 * std::sin(x * y);
      sigma[i] << sxx, sxy, 0.0, sxy, syy, 0.0, 0.0, 0.0, 0.3 * (sxx + syy);
      eps[i] = std::max(0.0, 0.4 * std::sin(0.8 * x) * std::cos(0.5 * y));
      det[i] = 1.0 + 1e-3 * std::sin(x + y);
      out.points.push_back(mesh.node[i] + u[i]);
    }
    out.data.add("displacement", u).add("velocity", v).add("stress", sigma);
    out.data.add("equivalent_plastic_strain", eps).add("det_F", det);
    return out;
  }();
  return s;
}

// Times write_vtu of the 10^6-particle snapshot in `format` on `threads` threads, to a file in
// the temporary directory (the page cache: the disk is not timed); counts the file's size.
void time_write(benchmark::State& state, int threads, const rkpm::io::vtu_format& format) {
  const auto& s = bench_snapshot(1000);
  const auto path = std::filesystem::temp_directory_path() / "rkpm_bench_snapshot.vtu";
  omp_set_num_threads(threads);
  for (auto _ : state) rkpm::io::write_vtu(path, s.points, s.cells, s.data, format);
  state.counters["file_MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  state.counters["particles"] = static_cast<double>(s.points.size());
  std::filesystem::remove(path);
}

void skip(benchmark::State& state, const char* why) {
  state.SkipWithError(why);
  for (auto _ : state) {
  }
}

void BM_write_vtu(benchmark::State& state) {
  rkpm::io::vtu_format format;
  format.deflater = state.range(1) ? rkpm::io::vtu_deflater::libdeflate : rkpm::io::vtu_deflater::zlib;
  format.zlib_level = static_cast<int>(state.range(2));
  if (!rkpm::io::vtu_deflater_available(format.deflater))
    return skip(state, "this build lacks the library (libdeflate-dev or zlib1g-dev)");
  time_write(state, static_cast<int>(state.range(0)), format);
}

void BM_write_vtu_lz4(benchmark::State& state) {
  if (!rkpm::io::vtu_lz4_available) return skip(state, "this build lacks liblz4 (liblz4-dev)");
  time_write(state, static_cast<int>(state.range(0)),
             {rkpm::io::vtu_encoding::appended, rkpm::io::vtu_compression::lz4});
}

void BM_write_vtu_uncompressed(benchmark::State& state) {
  time_write(state, static_cast<int>(state.range(0)),
             {rkpm::io::vtu_encoding::appended, rkpm::io::vtu_compression::none});
}

// The timing options of every benchmark here.
void timed(benchmark::internal::Benchmark* b) { b->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0); }
void on_1_and_2_threads(benchmark::internal::Benchmark* b) {
  b->Arg(1)->Arg(2)->ArgName("threads");
  timed(b);
}

}  // namespace

// Thread count x library (zlib, libdeflate: the runner's when compiled in) x level: 1 (the
// runner's) and 6 (zlib's default). Google Benchmark varies the first argument fastest: 1 and 2
// threads follow each other, then the other library, so the ratios compare runs seconds apart.
BENCHMARK(BM_write_vtu)
    ->ArgsProduct({{1, 2}, {0, 1}, {1, 6}})
    ->ArgNames({"threads", "libdeflate", "level"})
    ->Apply(timed);
BENCHMARK(BM_write_vtu_lz4)->Apply(on_1_and_2_threads);
BENCHMARK(BM_write_vtu_uncompressed)->Apply(on_1_and_2_threads);

BENCHMARK_MAIN();
