// rkpm::io::json: escaping and number text checked against RFC 8259 by hand, and the whole
// document parsed back by an independent reader (Python's json module via /usr/bin/python3).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <rkpm/io/json.hpp>
#include <rkpm/io/gnuplot.hpp>  // io::detail::run_capture

namespace fs = std::filesystem;
using rkpm::io::json;

namespace {

// Runs a command and returns its exit status and output (stdout and stderr).
using rkpm::io::detail::run_capture;

// The JSON number grammar of RFC 8259, written out independently of the writer.
bool is_json_number(const std::string& s) {
  static const std::regex grammar(R"(-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?)");
  return std::regex_match(s, grammar);
}

}  // namespace

TEST_CASE("json string escaping follows RFC 8259") {
  CHECK(json::quote("plain") == "\"plain\"");
  CHECK(json::quote("a\"b\\c") == R"("a\"b\\c")");
  CHECK(json::quote("\n\t\r\b\f") == R"("\n\t\r\b\f")");
  CHECK(json::quote(std::string("\x01\x1f\x7f", 3)) == "\"\\u0001\\u001f\x7f\"");
  CHECK(json::quote(std::string("nul\0in", 6)) == R"("nul\u0000in")");
  CHECK(json::quote("\xc3\xa9") == "\"\xc3\xa9\"");  // UTF-8 passes through
  CHECK(json::quote("/") == "\"/\"");
}

TEST_CASE("json numbers: shortest round-trip text, valid grammar, non-finite as null") {
  CHECK(json::number_text(0.1) == "0.1");
  CHECK(json::number_text(100) == "100");
  CHECK(json::number_text(-0.0) == "-0.0");
  CHECK(json::number_text(1e21) == "1e+21");
  CHECK(json::number_text(5e-324) == "5e-324");
  CHECK(json::number_text(std::nan("")) == "null");
  CHECK(json::number_text(-std::numeric_limits<double>::infinity()) == "null");

  std::mt19937_64 rng(7);
  for (int i = 0; i < 20000; ++i) {
    double x;
    const auto bits = rng();
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) continue;
    const auto text = json::number_text(x);
    INFO(text);
    REQUIRE(is_json_number(text));
    CHECK(std::strtod(text.c_str(), nullptr) == x);
    // Shortest: dropping one significant digit no longer reads back (17 digits always would).
    std::string mantissa = text.substr(0, text.find_first_of("eE"));
    std::erase_if(mantissa, [](char c) { return c < '0' || c > '9'; });
    const auto first = mantissa.find_first_not_of('0');
    const auto last = mantissa.find_last_not_of('0');
    const int digits = first == std::string::npos ? 0 : static_cast<int>(last - first + 1);
    if (digits > 1) {
      char shorter[64];
      std::snprintf(shorter, sizeof shorter, "%.*e", digits - 2, x);
      CHECK(std::strtod(shorter, nullptr) != x);
    }
  }
}

TEST_CASE("json structure: ordered keys, dump layouts, errors") {
  json j;
  j["z"] = 1;
  j["a"] = "two";
  j["m"]["inner"] = true;
  j["list"] = std::vector<double>{1.5, -2};
  j["z"] = 3;  // overwrite keeps the original position
  CHECK(j.dump(-1) == R"({"z":3,"a":"two","m":{"inner":true},"list":[1.5,-2]})");
  CHECK(j.dump(2) ==
        "{\n  \"z\": 3,\n  \"a\": \"two\",\n  \"m\": {\n    \"inner\": true\n  },\n  \"list\": [\n    1.5,\n    -2\n  ]\n}");
  CHECK(j.at("m").at("inner").as_bool());
  CHECK(j.at("list")[1].as_number() == -2);
  j["list"][0] = "first";  // literal 0 is an index, not a null key
  CHECK(j.at("list")[0].as_string() == "first");
  CHECK_THROWS_AS(j.at("list")[2], rkpm::error);
  CHECK(j.size() == 4);
  CHECK(json::array().dump() == "[]");
  CHECK(json::object().dump() == "{}");
  CHECK(json().dump() == "null");
  CHECK_THROWS_AS(j.at("missing"), rkpm::error);
  json s = "text";
  CHECK_THROWS_AS(s["key"], rkpm::error);
  CHECK_THROWS_AS(s.push_back(1), rkpm::error);
  CHECK_THROWS_AS(s.as_number(), rkpm::error);
}

TEST_CASE("json file parsed back by Python's json module") {
  const fs::path python = "/usr/bin/python3";
  REQUIRE_MESSAGE(fs::exists(python), "/usr/bin/python3 missing: install python3 (apt-get install python3)");
  const auto script = fs::path(__FILE__).parent_path() / "check_json.py";
  REQUIRE_MESSAGE(fs::exists(script), "helper script missing: " << script);

  json doc;
  doc["case"] = std::string("taylor \"bar\"\n\ttab\\ \x01\x1f/ \xc3\xa9 \xe2\x98\x83");
  std::vector<double> numbers = {0.0, -0.0, 0.1, 1.0 / 3.0, 1e21, 1e-7, 5e-324, 2.2250738585072014e-308,
                                 std::numeric_limits<double>::max(), 9007199254740993.0, 123456.0};
  std::mt19937_64 rng(11);
  while (numbers.size() < 500) {
    double x;
    const auto bits = rng();
    std::memcpy(&x, &bits, sizeof x);
    if (std::isfinite(x)) numbers.push_back(x);
  }
  doc["numbers"] = numbers;
  auto& hex = doc["hex"] = json::array();
  for (double x : numbers) hex.push_back(fmt::format("{:a}", x));  // exact, independent form
  doc["nonfinite"] = std::vector<double>{std::nan(""), std::numeric_limits<double>::infinity(),
                                         -std::numeric_limits<double>::infinity()};
  doc["flags"]["ok"] = true;
  doc["flags"]["bad"] = false;
  doc["flags"]["none"] = nullptr;
  doc["order"]["z"] = 1;
  doc["order"]["a"] = 2;
  doc["order"]["m"] = 3;
  doc["empty_array"] = json::array();
  doc["empty_object"] = json::object();

  const auto dir = fs::temp_directory_path() / ("rkpm_unit_io_json_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  for (int indent : {2, -1}) {
    const auto path = dir / "sub" / fmt::format("summary_{}.json", indent);
    rkpm::io::write_json(path, doc, indent);
    const auto [rc, out] = run_capture(python.string() + " '" + script.string() + "' '" + path.string() + "'");
    INFO("python output: " << out);
    CHECK(rc == 0);
  }
  fs::remove_all(dir);
}
