#pragma once
// PNG figures through gnuplot, driven by gnuplot-iostream (Debian libgnuplot-iostream-dev).
// gnuplot-iostream needs Boost.Iostreams, .System and .Filesystem at link time: a program that
// includes this header links rkpm::gnuplot (find_package(rkpm ... COMPONENTS gnuplot)), not
// only rkpm::rkpm.
//
//   rkpm::io::gnuplot_figure fig("radius.png", {.width = 900, .height = 700});
//   fig << "set xlabel 't (us)'\nplot '-' using 1:2 with lines notitle\n";
//   fig.send1d(std::make_pair(t, r));   // two std::vector<double> as columns, or rows of pairs
//   fig.render();                       // throws rkpm::error with gnuplot's message on failure
//
// The caller writes the plot commands and sends the data as arrays (one send per '-' in the
// plot commands); the terminal and output are set here: pngcairo, or libgd's png terminal when
// gnuplot was built without cairo. gnuplot_png() draws a script alone (data read from files).

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include <unistd.h>

#include <fmt/format.h>
#include <gnuplot-iostream.h>

#include <rkpm/core/error.hpp>
#include <rkpm/io/files.hpp>

namespace rkpm::io {

struct gnuplot_options {
  int width = 800;   // pixels
  int height = 600;  // pixels
  std::string font = "";  // e.g. "Sans,11"; empty keeps gnuplot's default
};

// gnuplot single-quoted string: '' stands for one quote and nothing else is special.
inline std::string gnuplot_quote(std::string_view s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') q += "''";
    else q += c;
  }
  return q + "'";
}

namespace detail {

// POSIX shell single-quoting: ' becomes '\''.
inline std::string shell_quote(std::string_view s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') q += "'\\''";
    else q += c;
  }
  return q + "'";
}

inline std::filesystem::path find_in_path(std::string_view program) {
  const char* path = std::getenv("PATH");
  std::string_view dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
  while (true) {
    const auto colon = dirs.find(':');
    const std::filesystem::path dir(std::string(dirs.substr(0, colon)));
    const auto candidate = (dir.empty() ? std::filesystem::path(".") : dir) / program;
    if (::access(candidate.c_str(), X_OK) == 0 && !std::filesystem::is_directory(candidate)) return candidate;
    if (colon == std::string_view::npos) return {};
    dirs.remove_prefix(colon + 1);
  }
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The last line gnuplot prints: its error count (GPVAL_ERRNO is non-zero once a command failed).
inline constexpr std::string_view status_marker = "rkpm-gnuplot-errno ";

}  // namespace detail

// True if a gnuplot executable is on PATH.
inline bool gnuplot_available() { return !detail::find_in_path("gnuplot").empty(); }

// One PNG drawn by one gnuplot process. Commands and data go to gnuplot as they are given;
// render() ends the script, waits for gnuplot and checks that it reported no error and wrote a
// PNG. A figure destroyed without render() (an exception on the way) closes gnuplot unchecked.
class gnuplot_figure {
 public:
  explicit gnuplot_figure(std::filesystem::path png_path, const gnuplot_options& options = {})
      : png_(std::move(png_path)), log_(std::filesystem::path(png_) += ".log") {
    if (!gnuplot_available())
      fail("gnuplot not found on PATH, needed to draw '{}': install it (apt-get install gnuplot-nox)", png_.string());
    ensure_parent_directory(png_);
    std::error_code ec;
    std::filesystem::remove(png_, ec);  // so that an old figure is never taken for a new one
    // gnuplot's messages (errors, warnings, the status line) go to a log beside the figure;
    // render() reads the outcome there ("|| true": gnuplot-iostream would print a line of its
    // own for a non-zero exit status).
    gp_.emplace("gnuplot 2>" + detail::shell_quote(log_.string()) + " || true");
    const std::string size = fmt::format("size {},{}{}", options.width, options.height,
                                         options.font.empty() ? "" : " font " + gnuplot_quote(options.font));
    *gp_ << fmt::format("if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {{\n  set terminal pngcairo {0}\n}} else {{\n"
                        "  set terminal png {0}\n}}\nset output {1}\n",
                        size, gnuplot_quote(png_.string()));
  }
  gnuplot_figure(const gnuplot_figure&) = delete;
  gnuplot_figure& operator=(const gnuplot_figure&) = delete;
  ~gnuplot_figure() {
    if (!gp_) return;
    gp_.reset();
    std::error_code ec;
    std::filesystem::remove(log_, ec);
  }

  // gnuplot commands (without terminal or output).
  gnuplot_figure& operator<<(std::string_view commands) {
    *gp_ << commands;
    return *this;
  }

  // The data of the next '-' in the plot commands: a container of rows (std::pair or std::tuple
  // of numbers) or a std::pair / std::tuple of equally long columns.
  template <class Data>
  gnuplot_figure& send1d(const Data& data) {
    gp_->send1d(data);
    return *this;
  }

  // Like send1d, for a container of blocks of rows: gnuplot ends a line at each block, so a
  // list of closed outlines (the cells of a mesh) draws as separate polygons.
  template <class Blocks>
  gnuplot_figure& send2d(const Blocks& blocks) {
    gp_->send2d(blocks);
    return *this;
  }

  // Finishes the figure. Throws rkpm::error with gnuplot's messages if a command failed, gnuplot
  // stopped early or no PNG came out.
  void render() {
    *gp_ << "\nunset output\nprint sprintf('" << detail::status_marker << "%d', GPVAL_ERRNO)\n";
    gp_.reset();  // closes the pipe and waits for gnuplot to exit
    const std::string log = detail::read_text(log_);
    std::error_code ec;
    std::filesystem::remove(log_, ec);
    const auto at = log.rfind(detail::status_marker);
    const std::string messages = log.substr(0, at == std::string::npos ? log.size() : at);
    if (at == std::string::npos || log.compare(at + detail::status_marker.size(), 2, "0\n") != 0)
      fail("gnuplot failed on '{}': {}; fix the plot commands or the data sent", png_.string(),
           messages.empty() ? std::string("it stopped before the end of the script") : trimmed(messages));
    unsigned char signature[8] = {};
    std::ifstream png(png_, std::ios::binary);
    if (!png || !png.read(reinterpret_cast<char*>(signature), 8) ||
        std::string_view(reinterpret_cast<char*>(signature), 8) != "\x89PNG\r\n\x1a\n")
      fail("gnuplot ran but '{}' is not a PNG ({}); check that the commands do not reset the terminal or output",
           png_.string(), messages.empty() ? std::string("no messages") : trimmed(messages));
  }

 private:
  static std::string trimmed(const std::string& s) {
    const auto first = s.find_first_not_of(" \n"), last = s.find_last_not_of(" \n");
    return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
  }

  std::filesystem::path png_, log_;
  std::optional<gnuplotio::Gnuplot> gp_;
};

// Renders `script` (gnuplot commands without terminal/output, data from files or inline
// `$name << EOD` blocks) into `png_path`. Throws rkpm::error if gnuplot is missing, reports an
// error, or writes no PNG.
inline void gnuplot_png(const std::filesystem::path& png_path, std::string_view script,
                        const gnuplot_options& options = {}) {
  gnuplot_figure figure(png_path, options);
  figure << script;
  figure.render();
}

}  // namespace rkpm::io
