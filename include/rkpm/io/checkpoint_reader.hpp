#pragma once
// checkpoint_reader: reads a checkpoint file (layout: io/checkpoint_format.hpp) and checks it
// whole before any section is used: the prefix, the section table, the header and every
// section against their CRC-32s, and that the parts tile the file. It refuses with a one-line
// rkpm::error naming the file and the reason: not a checkpoint, another format version, a
// truncated file, a damaged one (naming the part whose checksum fails), then, while sections
// are read, another configuration, other counts, a section out of place or of another value
// size. A solver is not half loaded from a damaged or truncated file. Classes read their
// sections through load(checkpoint_reader&). On one rank of several, a layout
// (io/checkpoint_layout.hpp) names the sections of the whole model's particles and points: the
// reader takes each local value from the whole array by its index there.

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/bitwise.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/checkpoint_format.hpp>
#include <rkpm/io/checkpoint_layout.hpp>
#include <rkpm/io/crc32.hpp>

namespace rkpm::io {

// A checkpoint refused as damaged or truncated. Its message ends with "restart from an earlier
// checkpoint", to which a caller that knows one (the runner's --restart) adds ": PATH".
class checkpoint_damaged : public error {
 public:
  using error::error;
};

class checkpoint_reader {
 public:
  // Reads the file, checks that it is a checkpoint of this format version, complete and intact,
  // and reads its header.
  explicit checkpoint_reader(const std::filesystem::path& path) : name_(path.string()) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("cannot read checkpoint '{}': the file does not exist or is not readable", name_);
    bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    check_all();
  }
  // A checkpoint's bytes held in memory (checkpoint_writer::close), called `name` in messages;
  // `section_checksums` false for bytes written without them (skip_section_checksums).
  checkpoint_reader(std::string bytes, std::string name, bool section_checksums = true)
      : name_(std::move(name)), bytes_(std::move(bytes)), section_checksums_(section_checksums) {
    check_all();
  }
  // ... and checks its identity against `expected`.
  checkpoint_reader(const std::filesystem::path& path, const checkpoint_identity& expected) : checkpoint_reader(path) {
    check_identity(expected);
  }
  checkpoint_reader(std::string bytes, std::string name, const checkpoint_identity& expected,
                    bool section_checksums = true)
      : checkpoint_reader(std::move(bytes), std::move(name), section_checksums) {
    check_identity(expected);
  }

 private:
  void check_all() {
    const std::uint64_t table = check_prefix();
    read_table(table);
    check_parts();
    read_header();
  }
  void check_identity(const checkpoint_identity& expected) const {
    const checkpoint_identity& id = header_.identity;
    if (id.configuration != expected.configuration)
      fail("checkpoint '{}' is of configuration '{}', this solver is '{}': restart with the same policies",
           name_, id.configuration, expected.configuration);
    const char* what[] = {"particles", "quadrature points", "contact slave particles", "tools"};
    const index_t have[] = {id.particles, id.points, id.slaves, id.tools};
    const index_t want[] = {expected.particles, expected.points, expected.slaves, expected.tools};
    for (int k = 0; k < 4; ++k)
      if (have[k] != want[k])
        fail("checkpoint '{}' has {} {}, this problem has {}: restart the same problem at the same resolution",
             name_, have[k], what[k], want[k]);
  }

 public:
  const checkpoint_header& header() const { return header_; }
  // Reads the whole model's sections into a rank's part (null: the arrays as they are).
  void set_layout(const checkpoint_layout* layout) { layout_ = layout; }

  // Section `name` into `values`, which must already have the stored size.
  template <bitwise_value T>
  void array(std::string_view name, std::vector<T>& values) {
    const section& s = open<T>(name);
    if (const std::vector<stored_index>* index = layout_ && !values.empty() ? layout_->whole_index(name) : nullptr) {
      if (index->size() != values.size())
        fail("checkpoint '{}': section '{}': this rank holds {} values but its layout maps {}", name_, name,
             values.size(), index->size());
      if (layout_->take_from_parts(name, {reinterpret_cast<char*>(values.data()), values.size() * sizeof(T)}, sizeof(T)))
        return;
      for (std::size_t i = 0; i < values.size(); ++i) {
        if (static_cast<std::uint64_t>((*index)[i]) >= s.count)
          fail("checkpoint '{}': section '{}' has {} values, this problem's value {} is beyond them: a different "
               "problem",
               name_, name, s.count, (*index)[i]);
        std::memcpy(static_cast<void*>(&values[i]), bytes_.data() + s.offset + (*index)[i] * sizeof(T), sizeof(T));
      }
      return;
    }
    if (s.count != values.size())
      fail("checkpoint '{}': section '{}' has {} values, this solver expects {}: a different problem", name_, name,
           s.count, values.size());
    take(values.data(), s);
  }
  // Section `name` whatever its size (at most `capacity` values).
  template <bitwise_value T>
  std::size_t array(std::string_view name, std::span<T> capacity) {
    const section& s = open<T>(name);
    if (s.count > capacity.size())
      fail("checkpoint '{}': section '{}' has {} values, more than the {} this solver holds", name_, name, s.count,
           capacity.size());
    take(capacity.data(), s);
    return static_cast<std::size_t>(s.count);
  }
  template <bitwise_value T>
  void value(std::string_view name, T& v) {
    if (array(name, std::span<T>(&v, 1)) != 1)
      fail("checkpoint '{}': section '{}' is empty, it should hold one value", name_, name);
  }

  // A part with its own sections (a class with load(checkpoint_reader&)).
  template <class Part>
  void part(Part& p) {
    p.load(*this);
  }

  // Checks that every section has been read.
  void finish() {
    if (next_ != sections_.size())
      fail("checkpoint '{}' is of another build: section '{}' follows the last one this build reads", name_,
           sections_[next_].name);
  }

  const std::string& file() const { return name_; }
  struct section : checkpoint_section {
    std::size_t offset = 0;  // of its values in the file
  };
  // The section table (checked), for a reader of the parts of a checkpoint (io/checkpoint_parts.hpp).
  const std::vector<section>& sections() const { return sections_; }

 private:
  // The fields of a checked part [at, end): one that would pass `end` makes get() false.
  struct fields {
    const std::string& bytes;
    std::size_t at, end;
    template <class T>
    bool get(T& v) {
      if (end - at < sizeof(T)) return false;
      std::memcpy(&v, bytes.data() + at, sizeof(T));
      at += sizeof(T);
      return true;
    }
    bool text(std::string& s) {
      std::uint64_t n = 0;
      if (!get(n) || n > end - at) return false;
      s.assign(bytes.data() + at, n);
      at += n;
      return true;
    }
  };

  [[noreturn]] void damaged(std::string_view what) const {
    throw checkpoint_damaged(fmt::format(
        "checkpoint '{}': {}: the file is damaged; restart from an earlier checkpoint", name_, what));
  }
  [[noreturn]] void truncated(std::string_view what) const {
    throw checkpoint_damaged(
        fmt::format("checkpoint '{}' is truncated: {}; restart from an earlier checkpoint", name_, what));
  }
  template <class T>
  T at(std::size_t offset) const {
    T v;
    std::memcpy(&v, bytes_.data() + offset, sizeof(T));
    return v;
  }
  std::uint32_t crc(std::size_t offset, std::size_t n) const { return crc32_of(bytes_.data() + offset, n); }

  // The magic, the format version and the file's size, which the prefix's checksum vouches for;
  // returns the table's offset.
  std::uint64_t check_prefix() const {
    constexpr std::size_t P = checkpoint_prefix_bytes, checked = P - 4, magic = checkpoint_magic.size();
    const std::size_t size = bytes_.size();
    const bool prefix_intact = size >= P && crc(0, checked) == at<std::uint32_t>(checked);
    // A prefix that checks once this build's magic and version are put back is a checkpoint of
    // this version whose magic or version number is damaged, not another file or version.
    if (size >= P && !prefix_intact) {
      std::string prefix(checkpoint_magic);
      prefix.append(reinterpret_cast<const char*>(&checkpoint_format_version), 4);
      prefix.append(bytes_.data() + magic + 4, checked - magic - 4);
      if (crc32_of(prefix.data(), prefix.size()) == at<std::uint32_t>(checked)) damaged("the header fails its checksum");
    }
    if (size < magic || std::memcmp(bytes_.data(), checkpoint_magic.data(), magic) != 0)
      fail("'{}' is not an rkpm checkpoint file (it does not start with {})", name_, checkpoint_magic);
    if (size < magic + 4) truncated(fmt::format("it has {} bytes, it ends in the format version", size));
    const auto version = at<std::uint32_t>(magic);
    // Versions before the checked prefix are taken as they read (they have no checksum).
    if (version != checkpoint_format_version && (prefix_intact || version < checkpoint_first_checked_version))
      fail("checkpoint '{}' has format version {}, this build reads version {}: restart with the build "
           "that wrote it",
           name_, version, checkpoint_format_version);
    if (size < P) truncated(fmt::format("it has {} bytes, it ends in its {}-byte prefix", size, P));
    if (!prefix_intact) damaged("the header fails its checksum");
    const auto file_size = at<std::uint64_t>(magic + 4), table = at<std::uint64_t>(magic + 12);
    if (size < file_size) truncated(fmt::format("it has {} of its {} bytes", size, file_size));
    if (size > file_size) damaged(fmt::format("it has {} bytes after its end", size - file_size));
    if (table < P || table > file_size - 4) damaged("its prefix places the section table outside the file");
    return table;
  }

  // The section table, once its checksum holds: the header's and the sections' extents and
  // checksums, which must tile the file between the prefix and the table.
  void read_table(std::uint64_t table) {
    const std::size_t end = bytes_.size() - 4;
    if (crc(table, end - table) != at<std::uint32_t>(end)) damaged("the section table fails its checksum");
    fields f{bytes_, table, end};
    std::uint64_t count = 0;
    bool ok = f.get(header_bytes_) && f.get(header_crc_) && f.get(count) && header_bytes_ <= table - checkpoint_prefix_bytes;
    std::size_t offset = checkpoint_prefix_bytes + (ok ? header_bytes_ : 0);
    for (std::uint64_t k = 0; ok && k < count; ++k) {
      section s;
      ok = f.text(s.name) && f.get(s.count) && f.get(s.value_bytes) && f.get(s.crc) && s.value_bytes > 0 &&
           s.count <= (table - offset) / s.value_bytes;
      s.offset = offset;
      offset += s.count * s.value_bytes;
      sections_.push_back(std::move(s));
    }
    if (!ok || f.at != end || offset != table) damaged("its section table does not describe the file");
  }

  // The header's and every section's checksum, before anything of them is used.
  void check_parts() const {
    if (crc(checkpoint_prefix_bytes, header_bytes_) != header_crc_) damaged("the header fails its checksum");
    if (!section_checksums_) return;
    for (const section& s : sections_)
      if (crc(s.offset, s.count * s.value_bytes) != s.crc) damaged(fmt::format("section '{}' fails its checksum", s.name));
  }

  void read_header() {
    fields f{bytes_, checkpoint_prefix_bytes, checkpoint_prefix_bytes + header_bytes_};
    checkpoint_identity& id = header_.identity;
    bool ok = f.text(id.configuration);
    for (index_t* n : {&id.particles, &id.points, &id.slaves, &id.tools}) {
      std::uint64_t v = 0;
      ok = ok && f.get(v);
      *n = static_cast<index_t>(v);
    }
    if (!(ok && f.text(header_.description) && f.at == f.end)) damaged("its header's fields do not fill the header");
  }

  // The next section, which must be `name` with values of T.
  template <class T>
  const section& open(std::string_view name) {
    if (next_ == sections_.size())
      fail("checkpoint '{}' is of another build: it ends where section '{}' was expected", name_, name);
    const section& s = sections_[next_];
    if (s.name != name)
      fail("checkpoint '{}' is of another build: section '{}' where '{}' was expected", name_, s.name, name);
    if (s.value_bytes != sizeof(T))
      fail("checkpoint '{}': section '{}' holds values of {} bytes, this build's are {} bytes", name_, name,
           s.value_bytes, sizeof(T));
    ++next_;
    return s;
  }
  template <class T>
  void take(T* out, const section& s) {
    if (s.count > 0) std::memcpy(static_cast<void*>(out), bytes_.data() + s.offset, s.count * sizeof(T));
  }

  std::string name_;
  std::string bytes_;
  bool section_checksums_ = true;
  checkpoint_header header_;
  std::uint64_t header_bytes_ = 0;
  std::uint32_t header_crc_ = 0;
  std::vector<section> sections_;
  std::size_t next_ = 0;
  const checkpoint_layout* layout_ = nullptr;
};

// The header of a checkpoint (configuration, counts, description), checked to be a complete and
// intact checkpoint of this format version, without a solver: what a restart needs to rebuild one.
inline checkpoint_header read_checkpoint_header(const std::filesystem::path& path) {
  return checkpoint_reader(path).header();
}

}  // namespace rkpm::io
