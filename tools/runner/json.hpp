#pragma once
// The runner's JSON (summary.json) through nlohmann-json. ordered_json keeps object keys in the
// order they were set, so a summary reads in the order it was built; NaN and infinities have
// no JSON form and nlohmann writes them as null.

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include <rkpm/io/files.hpp>

namespace rkpm::runner {

using json = nlohmann::ordered_json;

// Writes `value` (indented by 2) through a temporary file and a rename, so a reader never sees
// half a summary. Text that is not UTF-8 (an error message quoting a path) is written with
// U+FFFD in place of the bad bytes rather than failing.
inline void write_json(const std::filesystem::path& path, const json& value) {
  io::replace_file(path, value.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

}  // namespace rkpm::runner
