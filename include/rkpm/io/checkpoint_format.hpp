#pragma once
// The checkpoint file format (docs/method.md section 9.5): a solver's complete state, read back
// bit for bit, every byte under a CRC-32 (io/crc32.hpp). Layout (integers little-endian):
//   prefix, 32 bytes            "RKPMCKPT"; format version (uint32, checkpoint_format_version);
//                               file size and table offset (uint64 each); the CRC-32 of these
//                               28 bytes (uint32). The size tells a truncated file from a
//                               damaged one; every version from checkpoint_first_checked_version
//                               on starts so, so that a damaged version number is not mistaken
//                               for another version.
//   header                      configuration name (uint64 length + bytes), the particle,
//                               quadrature-point, contact-slave and tool counts (uint64 each),
//                               free text of the writer (uint64 length + bytes), e.g. the run's
//                               case and parameters, for a restart to rebuild the same problem
//   values                      each section's values' raw bytes (bitwise_value types), in
//                               order, back to back
//   table, at the table offset  the header's byte count (uint64) and CRC-32 (uint32); the
//                               section count (uint64); per section its name (uint64 length +
//                               bytes), value count and bytes per value (uint64 each) and the
//                               CRC-32 of its values (uint32)
//   the table's CRC-32          uint32, the file's last 4 bytes
// The parts tile the file: no padding, nothing between them unchecked. The table is written
// last (its checksums are known then) and read first: a section's extent and name come from
// checked bytes, so the damaged section is named even when its own bytes are garbage.
// Writing: io/checkpoint_writer.hpp; reading and its checks: io/checkpoint_reader.hpp. These
// live in io/, not solver/, because contact policies save their state too and contact/ does not
// depend on solver/.

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/types.hpp>

namespace rkpm::io {

static_assert(std::endian::native == std::endian::little, "checkpoints store raw little-endian values");

inline constexpr std::string_view checkpoint_magic = "RKPMCKPT";
// Raise whenever the header or a section is added, removed, reordered or changes its value type.
// 2: F, tau and the J2 state as block entries (core/block_matrix.hpp), no points.F for J2.
// 3: no points.det_F and points.stretch; no points.tau when the material recomputes tau.
// 4: the checked prefix, a CRC-32 per part, the section table; no "end" section;
//    solver.tool_impulse and solver.tool_impulse_carry (each tool's impulse since t = 0, summed
//    with compensation).
inline constexpr std::uint32_t checkpoint_format_version = 4;
// Earlier versions have no checked prefix: their version number is taken as it reads.
inline constexpr std::uint32_t checkpoint_first_checked_version = 4;
inline constexpr std::size_t checkpoint_prefix_bytes = 32;
inline constexpr std::string_view checkpoint_extension = ".rkpmcp";

// What a checkpoint must match to be read into a solver.
struct checkpoint_identity {
  std::string configuration;  // e.g. Config::name()
  index_t particles = 0, points = 0, slaves = 0, tools = 0;
};

// What precedes the sections.
struct checkpoint_header {
  checkpoint_identity identity;
  std::string description;
};

// A section as the table lists it; its values start where the previous section's end.
struct checkpoint_section {
  std::string name;
  std::uint64_t count = 0, value_bytes = 0;  // values, and bytes per value
  std::uint32_t crc = 0;                     // of the values' bytes
};

// "checkpoint_0000001234.rkpmcp": file names that sort in step (so time) order.
inline std::string checkpoint_file_name(index_t step) {
  return fmt::format("checkpoint_{:010d}{}", step, checkpoint_extension);
}

// The checkpoints of a folder (checkpoint_file_name), in name (so step) order; temporary files
// of an interrupted write are not checkpoints.
inline std::vector<std::filesystem::path> checkpoints_in(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> found;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("checkpoint_") && entry.path().extension() == checkpoint_extension)
      found.push_back(entry.path());
  }
  std::ranges::sort(found, {}, [](const std::filesystem::path& p) { return p.filename().string(); });
  return found;
}

// The checkpoint of a folder with the latest name, if any.
inline std::optional<std::filesystem::path> latest_checkpoint(const std::filesystem::path& folder) {
  auto found = checkpoints_in(folder);
  if (found.empty()) return std::nullopt;
  return found.back();
}

}  // namespace rkpm::io
