// rkpm::io::csv_writer: values read back with strtod (independent of fmt) are the same
// doubles, the header is intact, rows are on disk before the writer closes, errors are clear.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <rkpm/io/csv.hpp>

namespace test_unit_io_csv {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  auto dir = fs::temp_directory_path() / ("rkpm_unit_io_csv_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  return dir;
}

std::vector<std::string> lines_of(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<double> parse_row(const std::string& line) {
  std::vector<double> v;
  const char* s = line.c_str();
  while (*s) {
    char* end = nullptr;
    v.push_back(std::strtod(s, &end));
    REQUIRE(end != s);
    s = end;
    if (*s == ',') ++s;
    else REQUIRE(*s == '\0');
  }
  return v;
}

bool same_double(double a, double b) {
  if (std::isnan(a)) return std::isnan(b);
  return a == b && std::signbit(a) == std::signbit(b);
}

}  // namespace

TEST_CASE("csv round trip: every double reads back bit-identical, rows flushed as written") {
  const auto dir = scratch("roundtrip");
  const auto path = dir / "deep" / "er" / "history.csv";  // parent directories are created

  std::vector<std::vector<double>> rows = {
      {0.0, -0.0, 1.0},
      {0.1, 1.0 / 3.0, -2.5e-300},
      {std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min(),
       std::numeric_limits<double>::min()},
      {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
       std::numeric_limits<double>::quiet_NaN()},
      {123456789012345678.0, 9007199254740993.0, 1e21}};
  std::mt19937_64 rng(42);
  for (int r = 0; r < 200; ++r) {
    std::vector<double> row(3);
    for (auto& x : row) {
      do {  // random bit patterns cover every exponent
        const auto bits = rng();
        std::memcpy(&x, &bits, sizeof x);
      } while (!std::isfinite(x));
    }
    rows.push_back(row);
  }

  rkpm::io::csv_writer csv(path, {"t", "energy", "force_y"});
  csv.row({rows[0][0], rows[0][1], rows[0][2]});  // initializer_list overload
  // Flushed per row: a reader sees the header and the first row while the writer is open.
  {
    const auto lines = lines_of(path);
    REQUIRE(lines.size() == 2);
    CHECK(lines[0] == "t,energy,force_y");
  }
  for (std::size_t r = 1; r < rows.size(); ++r) csv.row(rows[r]);  // span overload

  const auto lines = lines_of(path);
  REQUIRE(lines.size() == rows.size() + 1);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto back = parse_row(lines[r + 1]);
    REQUIRE(back.size() == 3);
    for (int c = 0; c < 3; ++c) {
      INFO("row " << r << " col " << c << " text '" << lines[r + 1] << "'");
      CHECK(same_double(back[c], rows[r][c]));
    }
  }
  CHECK(lines[2] == "0.1,0.3333333333333333,-2.5e-300");  // shortest form, not 17 digits
  fs::remove_all(dir);
}

TEST_CASE("csv: column names that need quoting are quoted (RFC 4180)") {
  const auto dir = scratch("quoting");
  {
    rkpm::io::csv_writer csv(dir / "q.csv", {"a,b", "say \"hi\"", "plain"});
    csv.row({1, 2, 3});
  }
  const auto lines = lines_of(dir / "q.csv");
  REQUIRE(lines.size() == 2);
  CHECK(lines[0] == R"("a,b","say ""hi""",plain)");
  CHECK(lines[1] == "1,2,3");
  fs::remove_all(dir);
}

TEST_CASE("csv errors name the path and the fix") {
  const auto dir = scratch("errors");
  fs::create_directories(dir);
  { std::ofstream(dir / "a_file") << "x"; }
  // A regular file where a directory is needed: cannot be created.
  try {
    rkpm::io::csv_writer csv(dir / "a_file" / "h.csv", {"t"});
    FAIL("no exception");
  } catch (const rkpm::error& e) {
    CHECK(std::string(e.what()).find("a_file") != std::string::npos);
  }
  // A directory where the file should be: cannot be opened.
  fs::create_directories(dir / "is_dir.csv");
  try {
    rkpm::io::csv_writer csv(dir / "is_dir.csv", {"t"});
    FAIL("no exception");
  } catch (const rkpm::error& e) {
    CHECK(std::string(e.what()).find("is_dir.csv") != std::string::npos);
  }
  rkpm::io::csv_writer csv(dir / "ok.csv", {"t", "x"});
  CHECK_THROWS_AS(csv.row({1.0}), rkpm::error);
  CHECK_THROWS_AS(rkpm::io::csv_writer(dir / "none.csv", std::vector<std::string>{}), rkpm::error);
  fs::remove_all(dir);
}

}  // namespace test_unit_io_csv
