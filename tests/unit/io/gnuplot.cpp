// rkpm::io::gnuplot_figure / gnuplot_png (gnuplot-iostream): real PNGs from arrays sent to
// gnuplot and from a CSV file (signature, IHDR size as requested, non-trivial size), and clear
// errors for a bad script, data that does not match the plot, or a missing gnuplot.
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

namespace test_unit_io_gnuplot {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

namespace fs = std::filesystem;

namespace {

fs::path figure_scratch() { return fs::temp_directory_path() / ("rkpm_unit_io_gnuplot_" + std::to_string(::getpid())); }

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

TEST_CASE("gnuplot is installed (gnuplot-nox)") {
  REQUIRE_MESSAGE(rkpm::io::gnuplot_available(), "gnuplot missing: apt-get install gnuplot-nox");
}

TEST_CASE("gnuplot_figure from arrays: columns, rows and blocks") {
  std::vector<double> x, y;
  for (int i = 0; i <= 100; ++i) {
    x.push_back(i * 0.01);
    y.push_back(std::sin(6.283185307179586 * x.back()));
  }
  // Two unit squares as closed outlines, one block each (a line break between them).
  const std::vector<std::vector<std::pair<double, double>>> cells{
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}, {{2, 0}, {3, 0}, {3, 1}, {2, 1}, {2, 0}}};
  const std::vector<std::pair<double, double>> points{{0.5, 0.5}, {2.5, 0.5}};

  const auto png = figure_scratch() / "figs" / "it's a sine.png";  // quote in the name on purpose
  {
    rkpm::io::gnuplot_figure fig(png, {.width = 640, .height = 480});
    fig << "set multiplot layout 1,2\nset xlabel 'x'\n"
           "plot '-' using 1:2 with lines title 'sin'\n";
    fig.send1d(std::make_pair(x, y));
    fig << "plot '-' using 1:2 with lines title 'cells', '-' using 1:2 with points title 'centres'\n";
    fig.send2d(cells).send1d(points);
    fig << "unset multiplot\n";
    fig.render();
  }
  REQUIRE(fs::exists(png));
  const auto [w, h] = png_size(png);
  CHECK(w == 640);
  CHECK(h == 480);
  CHECK(fs::file_size(png) > 2000);  // axes, labels and curves, not an empty image
  CHECK_FALSE(fs::exists(fs::path(png) += ".log"));  // gnuplot's log removed after success
  fs::remove_all(figure_scratch());
}

TEST_CASE("gnuplot_png from a CSV time history") {
  const auto csv_path = figure_scratch() / "history.csv";
  {
    rkpm::io::csv_writer csv(csv_path, {"t", "kinetic", "internal"});
    for (int i = 0; i <= 50; ++i) csv.row({i * 1e-6, 1.0 - i / 50.0, i / 50.0});
  }
  const auto png = figure_scratch() / "energy.png";
  rkpm::io::gnuplot_png(png,
                        "set datafile separator ','\nset key autotitle columnhead\n"
                        "plot '" + csv_path.string() + "' using 1:2 with lines, '' using 1:3 with lines\n");
  const auto [w, h] = png_size(png);
  CHECK(w == 800);
  CHECK(h == 600);
  CHECK(fs::file_size(png) > 2000);
  fs::remove_all(figure_scratch());
}

TEST_CASE("gnuplot errors: a bad script or missing data reports gnuplot's message; no gnuplot names the package") {
  const auto png = figure_scratch() / "bad.png";
  try {
    rkpm::io::gnuplot_png(png, "plot $nosuchblock using 1:2\n");
    FAIL("no exception");
  } catch (const rkpm::error& e) {
    const std::string what = e.what();
    CHECK(what.find("gnuplot failed") != std::string::npos);
    CHECK(what.find("nosuchblock") != std::string::npos);
  }
  CHECK_FALSE(fs::exists(fs::path(png) += ".log"));
  // Two '-' in the plot command, one data set sent: gnuplot takes the status line for data.
  try {
    rkpm::io::gnuplot_figure fig(png);
    fig << "plot '-' using 1:2 with lines, '-' using 1:2 with lines\n";
    fig.send1d(std::vector<std::pair<double, double>>{{0, 0}, {1, 1}});
    fig.render();
    FAIL("no exception");
  } catch (const rkpm::error& e) {
    CHECK(std::string(e.what()).find("gnuplot failed") != std::string::npos);
  }
  // A figure abandoned before render() (an exception on the way) closes gnuplot quietly.
  { rkpm::io::gnuplot_figure fig(png); fig << "plot '-' using 1:2\n"; }

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
  fs::remove_all(figure_scratch());
}

}  // namespace test_unit_io_gnuplot
