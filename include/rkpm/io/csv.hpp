#pragma once
// rkpm::io::csv_writer: time histories as CSV (docs/method.md section 9.4). One header row of column
// names, then one row of doubles per call, written in shortest round-trip form (reading a value
// back with strtod gives the same double) and flushed per row, so a run that dies keeps every
// row it wrote.

#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <iterator>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>
#include <rkpm/io/files.hpp>

namespace rkpm::io {

class csv_writer {
 public:
  // Opens (truncates) `path`, creating its parent directories, and writes the header row.
  csv_writer(const std::filesystem::path& path, std::vector<std::string> columns)
      : path_(path), columns_(std::move(columns)) {
    if (columns_.empty()) fail("csv '{}': no columns given; name at least one column", path_.string());
    ensure_parent_directory(path_);
    file_ = std::fopen(path_.c_str(), "w");
    if (!file_)
      fail("cannot open CSV file '{}' for writing: check that the directory is writable",
           path_.string());
    std::string line;
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      if (c) line += ',';
      line += quoted(columns_[c]);
    }
    line += '\n';
    put(line);
  }
  csv_writer(const std::filesystem::path& path, std::initializer_list<std::string> columns)
      : csv_writer(path, std::vector<std::string>(columns)) {}

  csv_writer(const csv_writer&) = delete;
  csv_writer& operator=(const csv_writer&) = delete;
  csv_writer(csv_writer&& other) noexcept
      : path_(std::move(other.path_)), columns_(std::move(other.columns_)),
        line_(std::move(other.line_)), file_(std::exchange(other.file_, nullptr)) {}
  csv_writer& operator=(csv_writer&& other) noexcept {
    if (this != &other) {
      close();
      path_ = std::move(other.path_);
      columns_ = std::move(other.columns_);
      line_ = std::move(other.line_);
      file_ = std::exchange(other.file_, nullptr);
    }
    return *this;
  }
  ~csv_writer() { close(); }

  // One value per column, in header order.
  void row(std::span<const double> values) {
    if (!file_) fail("csv '{}': row written after close()", path_.string());
    if (values.size() != columns_.size())
      fail("csv '{}': row has {} values but the header has {} columns; give one value per column",
           path_.string(), values.size(), columns_.size());
    line_.clear();
    for (std::size_t c = 0; c < values.size(); ++c) {
      if (c) line_ += ',';
      // fmt's "{}" is the shortest string that reads back to the same double (Dragonbox).
      fmt::format_to(std::back_inserter(line_), "{}", values[c]);
    }
    line_ += '\n';
    put(line_);
  }
  void row(std::initializer_list<double> values) {
    row(std::span<const double>(values.begin(), values.size()));
  }

  void close() {
    if (file_) std::fclose(std::exchange(file_, nullptr));
  }

  const std::filesystem::path& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }

 private:
  // RFC 4180 quoting, only where a name needs it.
  static std::string quoted(const std::string& name) {
    if (name.find_first_of(",\"\n\r") == std::string::npos) return name;
    std::string q = "\"";
    for (char ch : name) {
      if (ch == '"') q += '"';
      q += ch;
    }
    return q + '"';
  }

  void put(const std::string& text) {
    if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fflush(file_) != 0)
      fail("error while writing CSV file '{}': check free disk space", path_.string());
  }

  std::filesystem::path path_;
  std::vector<std::string> columns_;
  std::string line_;  // reused so that a row per time step does not allocate once warmed up
  std::FILE* file_ = nullptr;
};

}  // namespace rkpm::io
