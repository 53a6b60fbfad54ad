// Consumer of an installed rkpm: builds RK shape functions (cubic kernel, linear correction)
// on a small grid and checks what linear reproduction guarantees at every point,
//   sum_I N_I = 1,  sum_I grad N_I = 0,  sum_I N_I X_I = x,  sum_I grad N_I (x) X_I = I.
// Then writes the particles as a compressed VTU snapshot, which needs the compression library
// the installed package links (libdeflate or zlib, re-found by rkpmConfig.cmake).
// Exit status 0 only if every check holds, so the packaging test fails on a wrong install
// as well as on wrong numbers.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/discretization/shape_table.hpp>
#include <rkpm/io/vtk.hpp>
#include <rkpm/kernel/cubic_spline.hpp>

int main() {
  using rkpm::vec2;
  try {
    const auto particles = rkpm::make_grid_particles<2>(vec2(0.0, 0.0), vec2(1.0, 0.6),
                                                        Eigen::Vector2i(6, 4), 2.0);
    const rkpm::neighbor_search<2> search(particles);
    // Irregular points, corners and edges included, so no symmetry can hide an error.
    std::vector<vec2> points;
    for (int i = 0; i <= 7; ++i)
      for (int j = 0; j <= 5; ++j)
        points.emplace_back(std::fmod(0.137 * i + 0.05 * j, 1.0), 0.6 * j / 5.0);
    const auto table =
        rkpm::build_shape_table<rkpm::kernel::cubic_spline, rkpm::correction::linear, 2>(search,
                                                                                         points);
    double worst = 0.0;
    for (rkpm::index_t p = 0; p < table.points(); ++p) {
      double sum = 0.0;
      vec2 sum_grad = vec2::Zero();
      vec2 x = vec2::Zero();
      rkpm::mat2 dx = rkpm::mat2::Zero();
      for (rkpm::index_t e = table.offset[p]; e < table.offset[p + 1]; ++e) {
        const vec2& X = particles.position[table.neighbor[e]];
        sum += table.N[e];
        sum_grad += table.grad[e];
        x += table.N[e] * X;
        dx += X * table.grad[e].transpose();
      }
      worst = std::max({worst, std::abs(sum - 1.0), sum_grad.lpNorm<Eigen::Infinity>(),
                        (x - points[p]).lpNorm<Eigen::Infinity>(),
                        (dx - rkpm::mat2::Identity()).lpNorm<Eigen::Infinity>()});
    }
    std::printf("rkpm consumer: %td points, %td entries, worst reproduction error %.3e\n",
                table.points(), table.entries(), worst);
    if (table.points() != static_cast<rkpm::index_t>(points.size()) || !(worst < 1e-10)) {
      std::printf("rkpm consumer: FAILED (tolerance 1e-10)\n");
      return 1;
    }
    const auto vtu = std::filesystem::temp_directory_path() / "rkpm_consumer_snapshot.vtu";
    rkpm::io::point_data data;
    data.add("volume", particles.volume);
    rkpm::io::write_vtu(vtu, particles.position, data);
    std::ifstream in(vtu, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::filesystem::remove(vtu);
    const bool compressed = text.find("compressor=\"vtkZLibDataCompressor\"") != std::string::npos;
    std::printf("rkpm consumer: VTU snapshot of %zu bytes, %s\n", text.size(),
                compressed ? (rkpm::io::vtu_libdeflate_available ? "compressed by libdeflate" : "compressed by zlib")
                           : "not compressed");
    if (compressed != rkpm::io::vtu_zlib_available) {
      std::printf("rkpm consumer: FAILED (the snapshot's compression)\n");
      return 1;
    }
    return 0;
  } catch (const rkpm::error& e) {
    std::printf("rkpm consumer: rkpm::error: %s\n", e.what());
    return 2;
  }
}
