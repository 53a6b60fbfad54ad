#pragma once
// checkpoint_writer: builds a checkpoint file (layout: io/checkpoint_format.hpp) in memory and
// puts it in place through a temporary file and a rename (io/files.hpp), so a run killed while
// writing leaves the previous checkpoint usable. Classes add their sections through
// save(checkpoint_writer&) const (see io/checkpoint.hpp).

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <rkpm/core/bitwise.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/checkpoint_format.hpp>
#include <rkpm/io/files.hpp>

namespace rkpm::io {

class checkpoint_writer {
 public:
  checkpoint_writer(std::filesystem::path path, const checkpoint_identity& id, std::string_view description = {})
      : path_(std::move(path)) {
    bytes_.append(checkpoint_magic);
    put(checkpoint_format_version);
    text(id.configuration);
    for (index_t n : {id.particles, id.points, id.slaves, id.tools}) put(static_cast<std::uint64_t>(n));
    text(description);
  }

  template <bitwise_value T>
  void array(std::string_view name, std::span<const T> values) {
    text(name);
    put(static_cast<std::uint64_t>(values.size()));
    put(static_cast<std::uint64_t>(sizeof(T)));
    bytes_.append(reinterpret_cast<const char*>(values.data()), values.size_bytes());
  }
  template <bitwise_value T>
  void array(std::string_view name, const std::vector<T>& values) {
    array(name, std::span<const T>(values));
  }
  template <bitwise_value T>
  void value(std::string_view name, const T& v) {
    array(name, std::span<const T>(&v, 1));
  }

  // A part with its own sections (a class with save(checkpoint_writer&) const).
  template <class Part>
  void part(const Part& p) {
    p.save(*this);
  }

  // Closes the file and puts it in place (temporary file and rename).
  void commit() {
    array("end", std::span<const char>());
    replace_file(path_, bytes_);
  }

 private:
  template <class T>
  void put(const T& v) {
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void text(std::string_view s) {
    put(static_cast<std::uint64_t>(s.size()));
    bytes_.append(s);
  }

  std::filesystem::path path_;
  std::string bytes_;
};

}  // namespace rkpm::io
