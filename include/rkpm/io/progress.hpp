#pragma once
// rkpm::io::progress_line: the one-line progress display of long runs (docs/method.md section 9.4):
//   [ 42%] t = 33.6 us  step 1200  3400 steps/s  eta 12 s
// Shown on a terminal only (or when forced), redrawn in place with '\r' at most a few times a
// second so that printing never costs the solver measurable time. The time unit is chosen
// once from t_end so the number does not jump between units during a run.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include <unistd.h>

#include <fmt/format.h>

namespace rkpm::io {

class progress_line {
 public:
  using clock = std::chrono::steady_clock;

  // Shown if `out` is a terminal or `force` is set; `min_interval` seconds between redraws.
  explicit progress_line(bool force = false, std::FILE* out = stderr, double min_interval = 0.25)
      : out_(out), min_interval_(min_interval),
        enabled_(out != nullptr && (force || ::isatty(::fileno(out)) == 1)) {}

  progress_line(const progress_line&) = delete;
  progress_line& operator=(const progress_line&) = delete;
  ~progress_line() { finish(); }

  bool enabled() const { return enabled_; }

  // Cheap when throttled: one clock read and a comparison.
  void update(double t, double t_end, long step) {
    if (!enabled_ || finished_) return;
    const auto now = clock::now();
    if (!started_) {
      started_ = true;
      start_ = now;
      t_start_ = t;
      step_start_ = step;
    } else if (seconds(last_draw_, now) < min_interval_) {
      last_t_ = t, last_t_end_ = t_end, last_step_ = step;
      return;
    }
    last_t_ = t, last_t_end_ = t_end, last_step_ = step;
    draw(now);
  }

  // Draws the last state once more (so the final line is current) and ends the line.
  void finish() {
    if (!enabled_ || finished_) return;
    finished_ = true;
    if (!started_) return;
    draw(clock::now());
    std::fputc('\n', out_);
    std::fflush(out_);
  }

  // "33.6 us": value in the unit suited to `scale` (s, ms, us or ns).
  static std::string format_time(double t, double scale) {
    const double a = std::abs(scale);
    if (a >= 1.0 || a == 0.0 || !std::isfinite(a)) return fmt::format("{:.1f} s", t);
    if (a >= 1e-3) return fmt::format("{:.1f} ms", t * 1e3);
    if (a >= 1e-6) return fmt::format("{:.1f} us", t * 1e6);
    return fmt::format("{:.1f} ns", t * 1e9);
  }

  // "12 s", "3 min 20 s", "2 h 05 min"; "?" when unknown.
  static std::string format_duration(double s) {
    if (!std::isfinite(s) || s < 0) return "?";
    const long r = std::lround(s);
    if (r < 60) return fmt::format("{} s", r);
    if (r < 3600) return fmt::format("{} min {:02d} s", r / 60, r % 60);
    return fmt::format("{} h {:02d} min", r / 3600, (r % 3600) / 60);
  }

  // The text of one progress line (without '\r'); eta_s < 0 or non-finite prints "?".
  static std::string format_line(double t, double t_end, long step, double steps_per_s, double eta_s) {
    const double fraction = t_end > 0 ? std::clamp(t / t_end, 0.0, 1.0) : 0.0;
    return fmt::format("[{:3d}%] t = {}  step {}  {:.0f} steps/s  eta {}",
                       static_cast<int>(std::floor(100.0 * fraction + 1e-9)), format_time(t, t_end), step,
                       std::isfinite(steps_per_s) ? steps_per_s : 0.0, format_duration(eta_s));
  }

 private:
  static double seconds(clock::time_point a, clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  }

  void draw(clock::time_point now) {
    last_draw_ = now;
    const double elapsed = seconds(start_, now);
    const double rate = elapsed > 0 ? static_cast<double>(last_step_ - step_start_) / elapsed : 0.0;
    // Time left from the simulated-time rate so far: explicit steps are roughly uniform in cost.
    const double done = last_t_ - t_start_;
    const double eta = (done > 0 && elapsed > 0) ? elapsed * (last_t_end_ - last_t_) / done : -1.0;
    std::string text = format_line(last_t_, last_t_end_, last_step_, rate, eta);
    // Pad over the remains of a longer previous line instead of using terminal escapes, so a
    // forced line in a log file stays plain text.
    const std::size_t width = text.size();
    if (width < drawn_width_) text.append(drawn_width_ - width, ' ');
    drawn_width_ = width;
    std::fputc('\r', out_);
    std::fputs(text.c_str(), out_);
    std::fflush(out_);
  }

  std::FILE* out_;
  double min_interval_;
  bool enabled_;
  bool started_ = false;
  bool finished_ = false;
  clock::time_point start_{}, last_draw_{};
  double t_start_ = 0, last_t_ = 0, last_t_end_ = 0;
  long step_start_ = 0, last_step_ = 0;
  std::size_t drawn_width_ = 0;
};

}  // namespace rkpm::io
