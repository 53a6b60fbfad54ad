#pragma once
// The checkpoint file format (docs/method.md section 9.5): a solver's complete state, read back
// bit for bit. Layout (integers little-endian):
//   "RKPMCKPT"                  8 bytes
//   format version              uint32, checkpoint_format_version
//   identity                    configuration name (uint64 length + bytes), then the particle,
//                               quadrature-point, contact-slave and tool counts (uint64 each)
//   description                 free text of the writer (uint64 length + bytes), e.g. the run's
//                               case and parameters, for a restart to rebuild the same problem
//   sections, in order          name (uint64 length + bytes), value count (uint64), bytes per
//                               value (uint64), the values' raw bytes (bitwise_value types)
//   "end"                       an empty section closing the file
// Writing: io/checkpoint_writer.hpp; reading and its checks: io/checkpoint_reader.hpp. These
// live in io/, not solver/, because contact policies save their state too and contact/ does not
// depend on solver/.

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include <rkpm/core/types.hpp>

namespace rkpm::io {

static_assert(std::endian::native == std::endian::little, "checkpoints store raw little-endian values");

inline constexpr std::string_view checkpoint_magic = "RKPMCKPT";
// Raise whenever the header or a section is added, removed, reordered or changes its value type.
// 2: F, tau and the J2 state as block entries (core/block_matrix.hpp), no points.F for J2.
// 3: no points.det_F and points.stretch; no points.tau when the material recomputes tau.
// 4: solver.tool_impulse (each tool's impulse since t = 0).
inline constexpr std::uint32_t checkpoint_format_version = 4;
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

// "checkpoint_0000001234.rkpmcp": file names that sort in step (so time) order.
inline std::string checkpoint_file_name(index_t step) {
  return fmt::format("checkpoint_{:010d}{}", step, checkpoint_extension);
}

// The checkpoint of a folder with the latest name (checkpoint_file_name), if any; temporary
// files of an interrupted write are not checkpoints.
inline std::optional<std::filesystem::path> latest_checkpoint(const std::filesystem::path& folder) {
  std::optional<std::filesystem::path> latest;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("checkpoint_") && entry.path().extension() == checkpoint_extension &&
        (!latest || name > latest->filename().string()))
      latest = entry.path();
  }
  return latest;
}

}  // namespace rkpm::io
