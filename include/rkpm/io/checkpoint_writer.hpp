#pragma once
// checkpoint_writer: builds a checkpoint file (layout: io/checkpoint_format.hpp) in memory and
// puts it in place through a temporary file and a rename (io/files.hpp), so a run killed while
// writing leaves the previous checkpoint usable. Classes add their sections through
// save(checkpoint_writer&) const (see io/checkpoint.hpp). Each section's CRC-32 is taken as it
// is added, the header's, the table's and the prefix's at commit().
// On one rank of several, a layout (io/checkpoint_layout.hpp) turns the sections of the whole
// model's particles and points into the whole arrays, gathered on the rank that writes; the
// other ranks take part in the gathers and write nothing.

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <rkpm/core/bitwise.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/checkpoint_format.hpp>
#include <rkpm/io/checkpoint_layout.hpp>
#include <rkpm/io/crc32.hpp>
#include <rkpm/io/files.hpp>

namespace rkpm::io {

class checkpoint_writer {
 public:
  checkpoint_writer(std::filesystem::path path, const checkpoint_identity& id, std::string_view description = {},
                    checkpoint_layout* layout = nullptr)
      : path_(std::move(path)), layout_(layout) {
    bytes_.resize(checkpoint_prefix_bytes);  // filled in by commit()
    text(bytes_, id.configuration);
    for (index_t n : {id.particles, id.points, id.slaves, id.tools}) put(bytes_, static_cast<std::uint64_t>(n));
    text(bytes_, description);
    header_bytes_ = bytes_.size() - checkpoint_prefix_bytes;
  }

  template <bitwise_value T>
  void array(std::string_view name, std::span<const T> values) {
    if (layout_ && !values.empty() && layout_->whole_index(name)) {  // (an empty array: the same on every rank)
      const std::string whole = layout_->gather(
          name, {reinterpret_cast<const char*>(values.data()), values.size_bytes()}, sizeof(T));
      sections_.push_back({std::string(name), whole.size() / sizeof(T), sizeof(T), checksum(whole.data(), whole.size())});
      bytes_ += whole;
      return;
    }
    const char* data = reinterpret_cast<const char*>(values.data());
    sections_.push_back({std::string(name), values.size(), sizeof(T), checksum(data, values.size_bytes())});
    bytes_.append(data, values.size_bytes());
  }
  template <bitwise_value T>
  void array(std::string_view name, const std::vector<T>& values) {
    array(name, std::span<const T>(values));
  }
  template <bitwise_value T>
  void value(std::string_view name, const T& v) {
    array(name, std::span<const T>(&v, 1));
  }

  // For bytes handed from one solver to another in memory (close(), parallel::mirror_state),
  // never for a file: the sections' CRC-32s are left 0 (computing them was an eighth of the time
  // of a run on 2 processes that writes a history row every 5 steps), and the reader is told to
  // skip them. The prefix, table and header keep theirs.
  void skip_section_checksums() { section_checksums_ = false; }

  // A part with its own sections (a class with save(checkpoint_writer&) const).
  template <class Part>
  void part(const Part& p) {
    p.save(*this);
  }

  // Appends the table, fills in the prefix and puts the file in place (temporary file and rename).
  void commit() {
    if (layout_ && !layout_->writes()) return;
    replace_file(path_, close());
  }

  // The file's bytes, complete (table and prefix added), for a caller that keeps them in memory
  // (parallel::mirror_state); empty on a rank of several that does not write. Ends the writer.
  std::string close() {
    if (layout_ && !layout_->writes()) return {};
    std::string table;
    put(table, header_bytes_);
    put(table, crc32_of(bytes_.data() + checkpoint_prefix_bytes, header_bytes_));
    put(table, static_cast<std::uint64_t>(sections_.size()));
    for (const checkpoint_section& s : sections_) {
      text(table, s.name);
      put(table, s.count);
      put(table, s.value_bytes);
      put(table, s.crc);
    }
    const std::uint64_t table_offset = bytes_.size();
    bytes_ += table;
    put(bytes_, crc32_of(table.data(), table.size()));

    std::string prefix(checkpoint_magic);
    put(prefix, checkpoint_format_version);
    put(prefix, static_cast<std::uint64_t>(bytes_.size()));
    put(prefix, table_offset);
    put(prefix, crc32_of(prefix.data(), prefix.size()));
    bytes_.replace(0, checkpoint_prefix_bytes, prefix);
    return std::move(bytes_);
  }

 private:
  template <class T>
  static void put(std::string& out, const T& v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  static void text(std::string& out, std::string_view s) {
    put(out, static_cast<std::uint64_t>(s.size()));
    out.append(s);
  }
  std::uint32_t checksum(const char* data, std::size_t n) const { return section_checksums_ ? crc32_of(data, n) : 0; }

  std::filesystem::path path_;
  bool section_checksums_ = true;
  checkpoint_layout* layout_ = nullptr;  // on one rank of several: the whole arrays from the ranks' parts
  std::string bytes_;
  std::uint64_t header_bytes_ = 0;
  std::vector<checkpoint_section> sections_;
};

}  // namespace rkpm::io
