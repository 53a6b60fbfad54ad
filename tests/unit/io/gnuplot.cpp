// rkpm::io::gnuplot_png: real PNGs from inline data and from a CSV file (signature, IHDR size
// as requested, non-trivial size), and clear errors for a bad script or a missing gnuplot.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <rkpm/io/csv.hpp>
#include <rkpm/io/gnuplot.hpp>

namespace fs = std::filesystem;

namespace {

fs::path scratch() { return fs::temp_directory_path() / ("rkpm_unit_io_gnuplot_" + std::to_string(::getpid())); }

// Checks the 8-byte PNG signature and returns (width, height) from the IHDR chunk.
std::pair<std::uint32_t, std::uint32_t> png_size(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::vector<unsigned char> b(24);
  REQUIRE(in.read(reinterpret_cast<char*>(b.data()), 24));
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  for (int i = 0; i < 8; ++i) REQUIRE(b[i] == signature[i]);
  REQUIRE(std::string(b.begin() + 12, b.begin() + 16) == "IHDR");
  auto be32 = [&](int at) {
    return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) | (std::uint32_t{b[at + 2]} << 8) | b[at + 3];
  };
  return {be32(16), be32(20)};
}

}  // namespace

TEST_CASE("gnuplot is installed (gnuplot-nox) and offers a PNG terminal") {
  REQUIRE_MESSAGE(rkpm::io::gnuplot_available(), "gnuplot missing: apt-get install gnuplot-nox");
  const auto& term = rkpm::io::gnuplot_png_terminal();
  CHECK((term == "pngcairo" || term == "png"));
}

TEST_CASE("gnuplot_png from an inline data block") {
  std::vector<double> x, y;
  for (int i = 0; i <= 100; ++i) {
    x.push_back(i * 0.01);
    y.push_back(std::sin(6.283185307179586 * x.back()));
  }
  const auto block = rkpm::io::gnuplot_datablock("curve", {x, y});
  CHECK(block.starts_with("$curve << EOD\n0 0\n0.01 "));
  CHECK(block.ends_with("\n1 -2.4492935982947064e-16\nEOD\n"));

  const auto png = scratch() / "figs" / "it's a sine.png";  // quote in the name on purpose
  rkpm::io::gnuplot_png(png, block + "set xlabel 'x'\nplot $curve using 1:2 with lines title 'sin'\n",
                        {.width = 640, .height = 480});
  REQUIRE(fs::exists(png));
  const auto [w, h] = png_size(png);
  CHECK(w == 640);
  CHECK(h == 480);
  CHECK(fs::file_size(png) > 2000);  // axes, labels and a curve, not an empty image
  CHECK_FALSE(fs::exists(fs::path(png) += ".gp"));  // script removed after success
  fs::remove_all(scratch());
}

TEST_CASE("gnuplot_png from a CSV time history") {
  const auto csv_path = scratch() / "history.csv";
  {
    rkpm::io::csv_writer csv(csv_path, {"t", "kinetic", "internal"});
    for (int i = 0; i <= 50; ++i) csv.row({i * 1e-6, 1.0 - i / 50.0, i / 50.0});
  }
  const auto png = scratch() / "energy.png";
  rkpm::io::gnuplot_png(png,
                        "set datafile separator ','\nset key autotitle columnhead\n"
                        "plot '" + csv_path.string() + "' using 1:2 with lines, '' using 1:3 with lines\n");
  const auto [w, h] = png_size(png);
  CHECK(w == 800);
  CHECK(h == 600);
  CHECK(fs::file_size(png) > 2000);
  fs::remove_all(scratch());
}

TEST_CASE("gnuplot errors: a bad script reports gnuplot's message; no gnuplot names the package") {
  const auto png = scratch() / "bad.png";
  try {
    rkpm::io::gnuplot_png(png, "plot $nosuchblock using 1:2\n");
    FAIL("no exception");
  } catch (const rkpm::error& e) {
    const std::string what = e.what();
    CHECK(what.find("gnuplot failed") != std::string::npos);
    CHECK(what.find("nosuchblock") != std::string::npos);
  }
  CHECK_THROWS_AS(rkpm::io::gnuplot_datablock("d", {std::vector<double>(3), std::vector<double>(2)}),
                  rkpm::error);

  const std::string saved = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", "/nonexistent-dir-for-rkpm-test", 1);
  try {
    rkpm::io::gnuplot_png(png, "plot x\n");
    ::setenv("PATH", saved.c_str(), 1);
    FAIL("no exception");
  } catch (const rkpm::error& e) {
    ::setenv("PATH", saved.c_str(), 1);
    CHECK(std::string(e.what()).find("apt-get install gnuplot-nox") != std::string::npos);
  }
  fs::remove_all(scratch());
}
