#pragma once
// pvd_series: the .pvd index of a time series of VTK snapshots (io/vtk.hpp writes each), valid
// after every added snapshot.

#include <filesystem>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/io/files.hpp>
#include <rkpm/io/vtk.hpp>

namespace rkpm::io {

// A .pvd collection: one DataSet per snapshot with its time, files given relative to the
// .pvd's directory. Every add() rewrites the whole index atomically, so a run that dies after
// any number of snapshots leaves a valid .pvd listing exactly those snapshots.
class pvd_series {
 public:
  // `entries`: snapshots already in the series (time, file relative to the .pvd), e.g. those of
  // the run a restart continues.
  explicit pvd_series(std::filesystem::path pvd_path, std::vector<std::pair<double, std::string>> entries = {})
      : path_(std::move(pvd_path)), entries_(std::move(entries)) {
    write();
  }

  void add(double time, const std::string& vtu_filename_relative) {
    entries_.emplace_back(time, vtu_filename_relative);
    write();
  }

  // The next snapshot's file: <pvd stem>_<index, 6 digits><extension>, next to the .pvd (a
  // snapshot written in pieces is its .pvtu index: io/pvtu.hpp).
  std::string next_file(std::string_view extension = ".vtu") const {
    return fmt::format("{}_{:06d}{}", path_.stem().string(), entries_.size(), extension);
  }

  // Writes next_file() next to the .pvd by write_vtu(file, args...), any of its forms (io/vtk.hpp:
  // points and cells given, handed over, or made piecewise; points alone, each a vertex cell),
  // and adds it; returns its path.
  template <class... WriteArgs>
  std::filesystem::path add_snapshot(double time, WriteArgs&&... args) {
    const std::string name = next_file();
    const auto vtu = path_.parent_path() / name;
    write_vtu(vtu, std::forward<WriteArgs>(args)...);
    add(time, name);
    return vtu;
  }

  const std::filesystem::path& path() const { return path_; }
  std::size_t size() const { return entries_.size(); }

 private:
  void write() const {
    std::string out =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"Collection\" version=\"0.1\">\n"
        "  <Collection>\n";
    for (const auto& [t, file] : entries_)
      fmt::format_to(std::back_inserter(out),
                     "    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t,
                     detail::xml_escape(file));
    out += "  </Collection>\n</VTKFile>\n";
    replace_file(path_, out);
  }

  std::filesystem::path path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace rkpm::io
