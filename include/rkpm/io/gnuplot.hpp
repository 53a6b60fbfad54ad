#pragma once
// PNG figures through gnuplot (design.md section 6: the paper's figures for each case).
// gnuplot_png() runs the gnuplot program on a script the caller writes (plot commands, data in
// inline `$name << EOD` blocks made by gnuplot_datablock() or CSV files read with
// `set datafile separator ','`), with the terminal and output set here: pngcairo, or the
// libgd png terminal when gnuplot was built without cairo. Errors name the fix.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>
#include <rkpm/io/files.hpp>

namespace rkpm::io {

struct gnuplot_options {
  int width = 800;   // pixels
  int height = 600;  // pixels
  std::string font = "";  // e.g. "Sans,11"; empty keeps gnuplot's default
};

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

// gnuplot single-quoted string: '' stands for one quote and nothing else is special.
inline std::string gnuplot_quote(std::string_view s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') q += "''";
    else q += c;
  }
  return q + "'";
}

// Runs a shell command, returns (exit status, combined stdout+stderr).
inline std::pair<int, std::string> run_capture(const std::string& command) {
  std::FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) fail("cannot start '{}': the system is out of processes or memory", command);
  std::string output;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, n);
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
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

}  // namespace detail

// True if a gnuplot executable is on PATH.
inline bool gnuplot_available() { return !detail::find_in_path("gnuplot").empty(); }

// The PNG terminal this gnuplot offers: "pngcairo" if built with cairo, else "png". Asked once.
inline const std::string& gnuplot_png_terminal() {
  static const std::string terminal = [] {
    const auto [status, output] = detail::run_capture("gnuplot -e \"set terminal pngcairo\"");
    return (status == 0 && output.find("unknown") == std::string::npos) ? std::string("pngcairo")
                                                                        : std::string("png");
  }();
  return terminal;
}

// An inline data block for a script:  $name << EOD / one row per index / EOD. Columns must
// have equal lengths; values are written in shortest round-trip form.
inline std::string gnuplot_datablock(std::string_view name, std::initializer_list<std::span<const double>> columns) {
  std::size_t rows = columns.size() ? columns.begin()->size() : 0;
  for (const auto& c : columns)
    if (c.size() != rows)
      fail("gnuplot data block ${}: columns of {} and {} values; give columns of equal length", name, rows,
           c.size());
  std::string out = fmt::format("${} << EOD\n", name);
  for (std::size_t r = 0; r < rows; ++r) {
    bool first = true;
    for (const auto& c : columns) {
      if (!first) out += ' ';
      first = false;
      fmt::format_to(std::back_inserter(out), "{}", c[r]);
    }
    out += '\n';
  }
  out += "EOD\n";
  return out;
}

// Renders `script` (gnuplot commands without terminal/output) into `png_path`. Throws
// rkpm::error if gnuplot is missing, reports an error, or writes no PNG.
inline void gnuplot_png(const std::filesystem::path& png_path, const std::string& script,
                        const gnuplot_options& options = {}) {
  if (!gnuplot_available())
    fail("gnuplot not found on PATH, needed to draw '{}': install it (apt-get install gnuplot-nox)",
         png_path.string());
  ensure_parent_directory(png_path);
  std::error_code ec;
  std::filesystem::remove(png_path, ec);  // so that an old figure is never taken for a new one

  std::string full = fmt::format("set terminal {} size {},{}", gnuplot_png_terminal(), options.width,
                                 options.height);
  if (!options.font.empty()) full += " font " + detail::gnuplot_quote(options.font);
  full += "\nset output " + detail::gnuplot_quote(png_path.string()) + "\n";
  full += script;
  full += "\nunset output\n";

  auto script_path = png_path;
  script_path += ".gp";
  replace_file(script_path, full);
  const auto [status, output] = detail::run_capture("gnuplot " + detail::shell_quote(script_path.string()));
  if (status != 0)
    fail("gnuplot failed on '{}' (exit {}):\n{}fix the script (kept in '{}')", png_path.string(), status,
         output, script_path.string());
  std::filesystem::remove(script_path, ec);

  unsigned char signature[8] = {};
  std::ifstream png(png_path, std::ios::binary);
  if (!png || !png.read(reinterpret_cast<char*>(signature), 8) ||
      std::string_view(reinterpret_cast<char*>(signature), 8) != "\x89PNG\r\n\x1a\n")
    fail("gnuplot ran but '{}' is not a PNG ({}); check that the script does not reset the terminal or output",
         png_path.string(), output.empty() ? "no messages" : output);
}

}  // namespace rkpm::io
