#pragma once
// checkpoint_reader: reads a checkpoint file (layout: io/checkpoint_format.hpp) and checks every
// field, refusing with a one-line rkpm::error naming the file and the reason: not a checkpoint,
// another format version, another configuration, other counts, a section out of place or of
// another value size, a truncated file (found before any section is read, so a solver is not
// half loaded from one). Classes read their sections through load(checkpoint_reader&).

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/bitwise.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/checkpoint_format.hpp>

namespace rkpm::io {

class checkpoint_reader {
 public:
  // Reads the file, checks that it is a complete checkpoint of this format version and reads
  // its header.
  explicit checkpoint_reader(const std::filesystem::path& path) : name_(path.string()) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("cannot read checkpoint '{}': the file does not exist or is not readable", name_);
    bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (bytes_.size() < checkpoint_magic.size() ||
        std::memcmp(bytes_.data(), checkpoint_magic.data(), checkpoint_magic.size()) != 0)
      fail("'{}' is not an rkpm checkpoint file (it does not start with {})", name_, checkpoint_magic);
    at_ = checkpoint_magic.size();
    const auto version = get<std::uint32_t>("the format version");
    if (version != checkpoint_format_version)
      fail("checkpoint '{}' has format version {}, this build reads version {}: restart with the build "
           "that wrote it",
           name_, version, checkpoint_format_version);
    checkpoint_identity& id = header_.identity;
    id.configuration = text("the configuration name");
    for (index_t* n : {&id.particles, &id.points, &id.slaves, &id.tools})
      *n = static_cast<index_t>(get<std::uint64_t>("the counts"));
    header_.description = text("the description");
    check_complete();
  }
  // ... and checks its identity against `expected`.
  checkpoint_reader(const std::filesystem::path& path, const checkpoint_identity& expected) : checkpoint_reader(path) {
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

  const checkpoint_header& header() const { return header_; }

  // Section `name` into `values`, which must already have the stored size.
  template <bitwise_value T>
  void array(std::string_view name, std::vector<T>& values) {
    const std::uint64_t n = open<T>(name);
    if (n != values.size())
      fail("checkpoint '{}': section '{}' has {} values, this solver expects {}: a different problem", name_, name,
           n, values.size());
    take(values.data(), n);
  }
  // Section `name` whatever its size (at most `capacity` values).
  template <bitwise_value T>
  std::size_t array(std::string_view name, std::span<T> capacity) {
    const std::uint64_t n = open<T>(name);
    if (n > capacity.size())
      fail("checkpoint '{}': section '{}' has {} values, more than the {} this solver holds", name_, name, n,
           capacity.size());
    take(capacity.data(), n);
    return static_cast<std::size_t>(n);
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
  void finish() { array("end", std::span<char>()); }

  const std::string& file() const { return name_; }

 private:
  // Walks the sections to the end marker before any is read, so that a truncated file is
  // refused before the solver is touched.
  void check_complete() {
    const std::size_t first = at_;
    for (;;) {
      const std::string name = text("a section name");
      const auto n = get<std::uint64_t>(name), size = get<std::uint64_t>(name);
      if (size == 0 || n > (bytes_.size() - at_) / size)
        fail("checkpoint '{}' is truncated: it ends in section '{}' ({} bytes); use an earlier checkpoint", name_,
             name, bytes_.size());
      at_ += n * size;
      if (name == "end") break;
    }
    if (at_ != bytes_.size())
      fail("checkpoint '{}' has {} bytes after its end section: a damaged file", name_, bytes_.size() - at_);
    at_ = first;
  }
  void need(std::uint64_t n, std::string_view what) const {
    if (n > bytes_.size() - at_)
      fail("checkpoint '{}' is truncated: it ends in {} ({} bytes, {} needed); use an earlier checkpoint", name_,
           what, bytes_.size(), at_ + n);
  }
  template <class T>
  T get(std::string_view what) {
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  std::string text(std::string_view what) {
    const auto n = get<std::uint64_t>(what);
    need(n, what);
    std::string s(bytes_.data() + at_, n);
    at_ += n;
    return s;
  }
  // Reads a section's header; returns its value count, its bytes checked to be present.
  template <class T>
  std::uint64_t open(std::string_view name) {
    const std::string where = fmt::format("section '{}'", name);
    const std::string found = text(where);
    if (found != name)
      fail("checkpoint '{}' is damaged or of another build: section '{}' where '{}' was expected", name_, found,
           name);
    const auto n = get<std::uint64_t>(where);
    const auto size = get<std::uint64_t>(where);
    if (size != sizeof(T))
      fail("checkpoint '{}': section '{}' holds values of {} bytes, this build's are {} bytes", name_, name, size,
           sizeof(T));
    if (n > (bytes_.size() - at_) / sizeof(T))
      fail("checkpoint '{}' is truncated: it ends in {} ({} bytes, {} values of {} bytes needed after byte {}); "
           "use an earlier checkpoint",
           name_, where, bytes_.size(), n, sizeof(T), at_);
    return n;
  }
  template <class T>
  void take(T* out, std::uint64_t n) {
    if (n > 0) std::memcpy(static_cast<void*>(out), bytes_.data() + at_, n * sizeof(T));
    at_ += n * sizeof(T);
  }

  std::string name_;
  checkpoint_header header_;
  std::vector<char> bytes_;
  std::size_t at_ = 0;
};

// The header of a checkpoint (configuration, counts, description), checked to be a complete
// checkpoint of this format version, without a solver: what a restart needs to rebuild one.
inline checkpoint_header read_checkpoint_header(const std::filesystem::path& path) {
  return checkpoint_reader(path).header();
}

}  // namespace rkpm::io
