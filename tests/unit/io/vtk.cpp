// VTK XML output read back by an independent reader: meshio under /usr/bin/python3
// (Debian python3-meshio) checks coordinates, vertex cells and every array's shape and values,
// recomputed in Python from the same closed formulas, for both encodings and for a .pvd series.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <rkpm/io/vtk.hpp>
#include <rkpm/io/gnuplot.hpp>  // io::detail::run_capture

namespace fs = std::filesystem;
using rkpm::mat3;
using rkpm::vec2;

namespace {

const fs::path python = "/usr/bin/python3";

// Runs a command and returns its exit status and output (stdout and stderr).
using rkpm::io::detail::run_capture;

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

// The same closed formulas as expected() in check_vtu.py.
struct snapshot {
  std::vector<vec2> points;
  rkpm::io::point_data data;
};
snapshot make(int n) {
  snapshot s;
  std::vector<double> eps(n), det(n);
  std::vector<vec2> u(n);
  std::vector<mat3> sigma(n);
  for (int k = 0; k < n; ++k) {
    const double i = k;
    s.points.emplace_back(i * 0.125 - 3.0 / 7.0, -i / 3.0 + 1e-7);
    eps[k] = i / 7.0 - 2.5;
    u[k] = vec2(i * 1e-6, -i / 3.0);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) sigma[k](r, c) = 1e8 * (i + 1.0) + 10.0 * r + c + 0.1;
    det[k] = 1.0 + i / 1024.0;
  }
  s.data.add("eps_p", eps).add("u", u).add("sigma", sigma).add("det F <J>", det);
  return s;
}

fs::path scratch() {
  auto dir = fs::temp_directory_path() / ("rkpm_unit_io_vtk_" + std::to_string(::getpid()));
  return dir;
}

}  // namespace

TEST_CASE("vtu: meshio reads points, vertex cells and scalar/vector/tensor arrays exactly") {
  const auto dir = scratch();
  for (auto encoding : {rkpm::io::vtu_encoding::binary, rkpm::io::vtu_encoding::ascii}) {
    for (int n : {1, 2, 3, 37}) {  // sizes that exercise every base64 padding case
      const bool binary = encoding == rkpm::io::vtu_encoding::binary;
      CAPTURE(binary);
      CAPTURE(n);
      const auto s = make(n);
      const auto path = dir / "one" / fmt::format("snap_{}_{}.vtu", binary ? "bin" : "txt", n);
      rkpm::io::write_vtu(path, s.points, s.data, encoding);
      check_with_meshio(fmt::format("vtu '{}' {}", path.string(), n));
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("vtu: an array of the wrong length is refused, naming the array") {
  const auto s = make(4);
  rkpm::io::point_data bad;
  bad.add("pressure", std::vector<double>(3, 1.0));
  try {
    rkpm::io::write_vtu(scratch() / "bad.vtu", s.points, bad);
    FAIL("no exception");
  } catch (const rkpm::error& e) {
    CHECK(std::string(e.what()).find("pressure") != std::string::npos);
  }
  CHECK_FALSE(fs::exists(scratch() / "bad.vtu"));
  rkpm::io::point_data twice;
  twice.add("a", std::vector<double>(4, 0.0));
  CHECK_THROWS_AS(twice.add("a", std::vector<double>(4, 0.0)), rkpm::error);
}

TEST_CASE("pvd: the index is valid after every addition and lists each added file") {
  const auto dir = scratch() / "series";
  rkpm::io::pvd_series pvd(dir / "run.pvd");
  // Valid (empty) collection before any snapshot.
  check_with_meshio(fmt::format("pvd '{}'", pvd.path().string()));

  const double times[] = {0.0, 1e-6, 2.5e-6};
  const int sizes[] = {5, 8, 13};
  std::string expect;
  for (int k = 0; k < 3; ++k) {
    const auto s = make(sizes[k]);
    const auto vtu = pvd.add_snapshot(times[k], s.points, s.data);
    CHECK(vtu.parent_path() == dir);
    CHECK(vtu.filename() == fmt::format("run_{:06d}.vtu", k));
    expect += fmt::format(" {},{}", times[k], sizes[k]);
    // As if the run died right here: the index on disk lists exactly the snapshots so far.
    check_with_meshio(fmt::format("pvd '{}'{}", pvd.path().string(), expect));
  }
  // add() with a caller-written file, named relative to the .pvd directory.
  const auto s = make(3);
  fs::create_directories(dir / "extra");
  rkpm::io::write_vtu(dir / "extra" / "late.vtu", s.points, s.data, rkpm::io::vtu_encoding::ascii);
  pvd.add(4e-6, "extra/late.vtu");
  CHECK(pvd.size() == 4);
  check_with_meshio(fmt::format("pvd '{}'{} 4e-06,3", pvd.path().string(), expect));
  CHECK_FALSE(fs::exists(dir / "run.pvd.tmp"));
  fs::remove_all(scratch());
}
