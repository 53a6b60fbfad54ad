// rkpm::io::progress_line: the text of the line, silence when not on a terminal, throttling,
// and a steps/s figure that matches a measured wall-clock interval.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include <rkpm/io/progress.hpp>

namespace test_unit_io_progress {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using rkpm::io::progress_line;

namespace {

std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) s.append(buf, n);
  return s;
}

int count(const std::string& s, char c) { return static_cast<int>(std::count(s.begin(), s.end(), c)); }

}  // namespace

TEST_CASE("progress text: units from the run length, durations, the whole line") {
  CHECK(progress_line::format_time(33.6e-6, 80e-6) == "33.6 us");
  CHECK(progress_line::format_time(0.0336, 0.1) == "33.6 ms");
  CHECK(progress_line::format_time(1.5, 10.0) == "1.5 s");
  CHECK(progress_line::format_time(2e-9, 5e-7) == "2.0 ns");
  CHECK(progress_line::format_time(1e-7, 1e-3) == "0.0 ms");  // unit fixed by t_end, not by t
  CHECK(progress_line::format_duration(12.4) == "12 s");
  CHECK(progress_line::format_duration(200) == "3 min 20 s");
  CHECK(progress_line::format_duration(7500) == "2 h 05 min");
  CHECK(progress_line::format_duration(-1) == "?");
  CHECK(progress_line::format_line(33.6e-6, 80e-6, 1200, 3400, 12) ==
        "[ 42%] t = 33.6 us  step 1200  3400 steps/s  eta 12 s");
  CHECK(progress_line::format_line(80e-6, 80e-6, 5000, 3400.4, 0) ==
        "[100%] t = 80.0 us  step 5000  3400 steps/s  eta 0 s");
  CHECK(progress_line::format_line(0, 80e-6, 0, 0, -1).starts_with("[  0%]"));
}

TEST_CASE("progress is silent on a file unless forced") {
  std::FILE* f = std::tmpfile();
  REQUIRE(f);
  {
    progress_line p(false, f, 0.0);
    CHECK_FALSE(p.enabled());
    for (int s = 0; s <= 100; ++s) p.update(s * 1e-6, 100e-6, s);
    p.finish();
  }
  CHECK(contents(f).empty());
  std::fclose(f);
}

TEST_CASE("forced progress: redraws in place, throttled, ends with the final state and a newline") {
  std::FILE* f = std::tmpfile();
  REQUIRE(f);
  {
    progress_line p(true, f, 3600.0);  // one redraw an hour: only the first update draws
    for (int s = 0; s <= 1000; ++s) p.update(s * 1e-7, 1e-4, s);
    p.finish();
  }
  const auto text = contents(f);
  CHECK(count(text, '\r') == 2);  // first update + finish
  CHECK(count(text, '\n') == 1);
  CHECK(text.back() == '\n');
  const auto last = text.substr(text.rfind('\r') + 1);
  CHECK(last.starts_with("[100%] t = 100.0 us  step 1000  "));
  std::fclose(f);
}

TEST_CASE("forced progress: steps/s and eta follow the wall clock") {
  std::FILE* f = std::tmpfile();
  REQUIRE(f);
  const auto t0 = std::chrono::steady_clock::now();
  double measured = 0;
  {
    progress_line p(true, f, 0.0);
    p.update(0.0, 1.0, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    measured = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    p.update(0.25, 1.0, 100);  // a quarter of the run in ~0.2 s: about 0.6 s left
  }
  const auto text = contents(f);
  const auto second = text.substr(text.find('\r', 1) + 1);
  INFO(second);
  REQUIRE(second.starts_with("[ 25%] t = 0.2 s  step 100  "));
  const double rate = std::strtod(second.c_str() + second.find("step 100  ") + 10, nullptr);
  // At most 100 steps in the measured >= 0.2 s; at least so on a loaded machine within 2 s.
  CHECK(rate <= 100 / 0.2 + 1);
  CHECK(rate >= 100 / std::max(2.0, measured));
  const auto eta_at = second.find("eta ");
  REQUIRE(eta_at != std::string::npos);
  const double eta = std::strtod(second.c_str() + eta_at + 4, nullptr);
  CHECK(eta >= 0);       // 3 x elapsed, rounded to whole seconds
  CHECK(eta <= 3 * 2.0 + 1);
  std::fclose(f);
}

}  // namespace test_unit_io_progress
