#pragma once
// Checkpoints in parts (docs/method.md section 9.5): a run on P processes may write its
// checkpoint as a folder of P files, part-K-of-P.rkpmcp, each written by process K alone
// (parallel/checkpoint_parts.hpp), so that no process gathers the whole state. Each part is a
// checkpoint file of the one format (io/checkpoint_format.hpp): the whole model's counts in its
// header, every section under its CRC-32. Its sections:
//   part.index, part.parts        K and P (uint64)
//   part.step, part.time          the state's step (uint64) and time (double), the same in every part
//   part.particles, part.points   the global indices of the particles and points process K owns
//                                 (increasing; the points' owners are parallel/global_blocks.hpp's)
//   the solver's sections         those of the whole model's particles and points hold the owned
//                                 values in that order; the others (time, energies, the contact's
//                                 per-slave state), which every process holds whole, are in every
//                                 part alike, so that any part is read as the first.
// A folder, not files side by side: the parts are written into a temporary folder that is renamed
// into place once every part is in it, so a set is whole or absent, and a folder of parts is
// listed among a folder's checkpoints (io::checkpoints_in) like one file.
// checkpoint_parts reads a set on any number of processes, one included (no MPI here): each takes
// its particles' and points' values by global index, part by part, holding one part's bytes at a
// time. Refused before anything is loaded (checkpoint_damaged, naming the part): a missing,
// damaged or truncated part, parts of different sets (another part count, another step, other
// shared sections), indices that do not tile the whole model.

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/checkpoint_format.hpp>
#include <rkpm/io/checkpoint_layout.hpp>
#include <rkpm/io/checkpoint_reader.hpp>
#include <rkpm/io/checkpoint_writer.hpp>
#include <rkpm/io/crc32.hpp>

namespace rkpm::io {

// "part-1-of-3.rkpmcp" in `folder`.
inline std::filesystem::path checkpoint_part_path(const std::filesystem::path& folder, std::uint64_t k,
                                                  std::uint64_t parts) {
  return folder / fmt::format("part-{}-of-{}{}", k, parts, checkpoint_extension);
}

// A set of parts refused: names the folder and the part.
[[noreturn]] inline void refuse_checkpoint_part(const std::filesystem::path& folder, const std::filesystem::path& part,
                                                std::string_view what) {
  throw checkpoint_damaged(fmt::format("checkpoint '{}': part '{}': {}; restart from an earlier checkpoint",
                                       folder.string(), part.string(), what));
}

// P of a folder of parts, from the parts' names, which must all say the same; refuses a missing part.
inline std::uint64_t checkpoint_part_count(const std::filesystem::path& folder) {
  if (!std::filesystem::is_directory(folder)) fail("cannot read checkpoint parts '{}': not a folder", folder.string());
  std::optional<std::uint64_t> P;
  std::filesystem::path named;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    const char* end = name.data() + name.size();
    std::uint64_t k = 0, n = 0;
    if (!name.starts_with("part-") || !name.ends_with(checkpoint_extension)) continue;
    auto r = std::from_chars(name.data() + 5, end, k);
    if (r.ec != std::errc() || !std::string_view(r.ptr, end).starts_with("-of-")) continue;
    r = std::from_chars(r.ptr + 4, end, n);
    if (r.ec != std::errc() || std::string_view(r.ptr, end) != checkpoint_extension) continue;
    if (P && *P != n)
      refuse_checkpoint_part(folder, entry.path(),
                             fmt::format("it is of a set of {} parts, '{}' of {}", n, named.string(), *P));
    P = n;
    named = entry.path();
  }
  if (!P)
    fail("checkpoint '{}' is a folder without checkpoint parts (part-K-of-P{})", folder.string(), checkpoint_extension);
  for (std::uint64_t k = 0; k < *P; ++k)
    if (!std::filesystem::exists(checkpoint_part_path(folder, k, *P)))
      refuse_checkpoint_part(folder, checkpoint_part_path(folder, k, *P), "it is missing");
  return *P;
}

// The header of a checkpoint file or of a folder of parts (every part there and intact; their
// first's header), without a solver: what a restart needs to rebuild the problem.
inline checkpoint_header read_any_checkpoint_header(const std::filesystem::path& path) {
  if (!std::filesystem::is_directory(path)) return read_checkpoint_header(path);
  const std::uint64_t P = checkpoint_part_count(path);
  const checkpoint_header first = read_checkpoint_header(checkpoint_part_path(path, 0, P));
  for (std::uint64_t k = 1; k < P; ++k)
    if (read_checkpoint_header(checkpoint_part_path(path, k, P)).description != first.description)
      refuse_checkpoint_part(path, checkpoint_part_path(path, k, P), "its description differs from part 0's");
  return first;
}

// The sections of the whole model's particles (or points) and this process's values of them.
struct checkpoint_whole_array {
  std::span<const std::string_view> sections;
  // Writing: the owned values' local positions, and their global indices (increasing).
  // Reading: every local value's global index (local unused).
  std::vector<stored_index> local, global;
};

// The part sections that open every part.
struct checkpoint_part_info {
  std::uint64_t index = 0, parts = 0, step = 0;
  double time = 0.0;
};

// Writing one part: the sections of the whole arrays become the owned values, in their order.
class checkpoint_part_layout final : public checkpoint_layout {
 public:
  checkpoint_part_layout(checkpoint_whole_array particles, checkpoint_whole_array points)
      : arrays_{std::move(particles), std::move(points)} {}
  const std::vector<stored_index>* whole_index(std::string_view section) const override {
    const checkpoint_whole_array* a = array_of(section);
    return a ? &a->global : nullptr;
  }
  std::string gather(std::string_view section, std::span<const char> local, std::size_t value_bytes) override {
    const checkpoint_whole_array& a = *array_of(section);
    std::string owned(a.local.size() * value_bytes, '\0');
    for (std::size_t k = 0; k < a.local.size(); ++k)
      std::memcpy(owned.data() + k * value_bytes, local.data() + a.local[k] * value_bytes, value_bytes);
    return owned;
  }
  bool writes() const override { return true; }

  // The part sections, before the solver's.
  void open_part(checkpoint_writer& w, const checkpoint_part_info& info) const {
    w.value("part.index", info.index);
    w.value("part.parts", info.parts);
    w.value("part.step", info.step);
    w.value("part.time", info.time);
    w.array("part.particles", arrays_[0].global);
    w.array("part.points", arrays_[1].global);
  }

 private:
  const checkpoint_whole_array* array_of(std::string_view section) const {
    for (const checkpoint_whole_array& a : arrays_)
      if (std::ranges::find(a.sections, section) != a.sections.end()) return &a;
    return nullptr;
  }
  checkpoint_whole_array arrays_[2];
};

// Reading a set of parts: reader() is the first part's reader, past its part sections, taking
// the whole arrays' values from every part through this layout (load the solver from it).
class checkpoint_parts final : public checkpoint_layout {
 public:
  checkpoint_parts(const std::filesystem::path& folder, const checkpoint_identity& expected,
                   checkpoint_whole_array particles, checkpoint_whole_array points)
      : folder_(folder.string()), arrays_{std::move(particles), std::move(points)} {
    const std::uint64_t P = checkpoint_part_count(folder);
    const index_t whole[2] = {expected.particles, expected.points};
    std::vector<std::pair<stored_index, stored_index>> sorted[2];  // (global, local) by global index
    std::vector<bool> held[2];
    for (int a = 0; a < 2; ++a) {
      for (std::size_t i = 0; i < arrays_[a].global.size(); ++i)
        sorted[a].emplace_back(arrays_[a].global[i], static_cast<stored_index>(i));
      std::ranges::sort(sorted[a]);
      held[a].assign(static_cast<std::size_t>(whole[a]), false);
    }
    checkpoint_part_info first;
    for (std::uint64_t k = 0; k < P; ++k) {
      part p{checkpoint_part_path(folder, k, P).string(), {}, {}};
      checkpoint_reader r(p.file, expected);
      checkpoint_part_info info;
      r.value("part.index", info.index);
      r.value("part.parts", info.parts);
      r.value("part.step", info.step);
      r.value("part.time", info.time);
      if (info.index != k || info.parts != P)
        refuse(p.file, fmt::format("it says it is part {} of {}", info.index, info.parts));
      if (k == 0) first = info;
      if (info.step != first.step || std::memcmp(&info.time, &first.time, sizeof(double)) != 0)
        refuse(p.file, fmt::format("it is of step {} (time {}), part 0 of step {} (time {}): parts of different "
                                   "checkpoints",
                                   info.step, info.time, first.step, first.time));
      for (int a = 0; a < 2; ++a) {
        const auto& table = r.sections();
        std::vector<stored_index> ids(table.size() > 4u + a ? table[4 + a].count : 0);
        r.array(a == 0 ? "part.particles" : "part.points", ids);
        for (std::size_t j = 0; j < ids.size(); ++j) {
          if (ids[j] < 0 || ids[j] >= whole[a] || (j > 0 && ids[j] <= ids[j - 1]))
            refuse(p.file, fmt::format("its {} indices are not increasing within the model", what_of(a)));
          if (held[a][ids[j]]) refuse(p.file, fmt::format("{} {} is in an earlier part too", what_of(a), ids[j]));
          held[a][ids[j]] = true;
        }
        // The local values this part holds: a merge of two increasing lists.
        auto it = sorted[a].begin();
        for (std::size_t j = 0; j < ids.size(); ++j) {
          while (it != sorted[a].end() && it->first < ids[j]) ++it;
          for (; it != sorted[a].end() && it->first == ids[j]; ++it)
            p.matches[a].emplace_back(static_cast<stored_index>(j), it->second);
        }
      }
      p.table = r.sections();
      check_table(p, k == 0 ? p.table : parts_[0].table);
      if (k == 0) first_.emplace(std::move(r));
      parts_.push_back(std::move(p));
    }
    for (int a = 0; a < 2; ++a)
      if (const auto gap = std::ranges::find(held[a], false); gap != held[a].end())
        refuse(checkpoint_part_path(folder, 0, P).string(),
               fmt::format("no part holds {} {}", what_of(a), gap - held[a].begin()));
    first_->set_layout(this);
  }
  checkpoint_parts(const checkpoint_parts&) = delete;  // its reader points to it
  checkpoint_parts& operator=(const checkpoint_parts&) = delete;

  checkpoint_reader& reader() { return *first_; }

  const std::vector<stored_index>* whole_index(std::string_view section) const override {
    const int a = array_of(section);
    return a < 0 ? nullptr : &arrays_[a].global;
  }
  std::string gather(std::string_view, std::span<const char>, std::size_t) override {
    fail("checkpoint parts of '{}' are read, not written, through this layout", folder_);
  }
  bool writes() const override { return false; }

  bool take_from_parts(std::string_view section, std::span<char> local, std::size_t value_bytes) const override {
    const int a = array_of(section);
    const auto& names = parts_[0].table;
    const auto at = std::ranges::find(names, section, &checkpoint_reader::section::name) - names.begin();
    for (const part& p : parts_) {
      if (p.matches[a].empty()) continue;
      const checkpoint_reader::section& s = p.table[at];
      std::string values(s.count * value_bytes, '\0');
      std::ifstream in(p.file, std::ios::binary);
      in.seekg(static_cast<std::streamoff>(s.offset));
      in.read(values.data(), static_cast<std::streamsize>(values.size()));
      if (!in || crc32_of(values.data(), values.size()) != s.crc)
        refuse(p.file, fmt::format("section '{}' changed since the part was checked", section));
      for (const auto& [j, i] : p.matches[a])
        std::memcpy(local.data() + i * value_bytes, values.data() + j * value_bytes, value_bytes);
    }
    return true;
  }

 private:
  struct part {
    std::string file;
    std::vector<checkpoint_reader::section> table;
    std::vector<std::pair<stored_index, stored_index>> matches[2];  // (value in the part, local value)
  };

  static const char* what_of(int a) { return a == 0 ? "particle" : "point"; }
  [[noreturn]] void refuse(const std::string& file, std::string_view what) const {
    refuse_checkpoint_part(folder_, file, what);
  }
  int array_of(std::string_view section) const {
    for (int a = 0; a < 2; ++a)
      if (std::ranges::find(arrays_[a].sections, section) != arrays_[a].sections.end()) return a;
    return -1;
  }

  // A part's section table against the first part's: the same sections in the same order, the
  // shared ones with the same values (their checksums), the whole arrays' with the part's count
  // (or empty in every part: a Lagrangian run's reference, solver/checkpoint.hpp).
  void check_table(const part& p, const std::vector<checkpoint_reader::section>& first) const {
    bool same = p.table.size() == first.size();
    for (std::size_t i = 6; same && i < first.size(); ++i) {
      const checkpoint_reader::section &s = p.table[i], &f = first[i];
      const int a = array_of(s.name);
      same = s.name == f.name && s.value_bytes == f.value_bytes &&
             (a < 0 ? s.count == f.count && s.crc == f.crc
                    : s.count == p.table[4 + a].count || (s.count == 0 && f.count == 0));
    }
    if (!same) refuse(p.file, "its sections differ from part 0's: parts of different checkpoints");
  }

  std::string folder_;
  checkpoint_whole_array arrays_[2];
  std::vector<part> parts_;
  std::optional<checkpoint_reader> first_;
};

}  // namespace rkpm::io
