#pragma once
// File helpers shared by the output writers (docs/method.md section 9.4):
// create the parent directories of an output path, and replace a whole file atomically so
// that a run killed while writing leaves either the previous or the new file, never half of it.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <system_error>

#include <rkpm/core/error.hpp>

namespace rkpm::io {

// Creates every missing directory above `path`; throws rkpm::error naming the directory.
inline void ensure_parent_directory(const std::filesystem::path& path) {
  const auto parent = path.parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(parent, ec);
  if (ec || !std::filesystem::is_directory(parent))
    fail("cannot create directory '{}' for output file '{}' ({}): check the path and its permissions",
         parent.string(), path.string(), ec ? ec.message() : "not a directory");
}

// Writes `path` through a temporary file in the same directory and a rename, which POSIX makes
// atomic: readers (ParaView polling a .pvd, a crashed run) never see a truncated file. `write`
// writes the content to the temporary file (a binary std::ofstream, which it may seek in); if
// it throws, the temporary file is removed and `path` left as it was.
inline void replace_file_with(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
  ensure_parent_directory(path);
  auto tmp = path;
  tmp += ".tmp";
  std::error_code ec;
  try {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      fail("cannot open '{}' for writing: check that the directory is writable", tmp.string());
    write(out);
    out.flush();
    if (!out) fail("error while writing '{}': check free disk space", tmp.string());
  } catch (...) {
    std::filesystem::remove(tmp, ec);
    throw;
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    fail("cannot rename '{}' to '{}': check that the target is not a directory and is writable",
         tmp.string(), path.string());
  }
}

// The same with the content in pieces, written one after the other (a large file need not be
// joined into one string first).
inline void replace_file(const std::filesystem::path& path, std::span<const std::string_view> pieces) {
  replace_file_with(path, [&](std::ostream& out) {
    for (const std::string_view content : pieces)
      out.write(content.data(), static_cast<std::streamsize>(content.size()));
  });
}

inline void replace_file(const std::filesystem::path& path, std::string_view content) {
  replace_file(path, std::span<const std::string_view>(&content, 1));
}

}  // namespace rkpm::io
