#pragma once
// Helpers for the case-file tests (tests/unit/case_file/): the repository's paper case files,
// a scratch folder per test program, and a case document written there and loaded (or the
// error its loading throws).

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <fmt/format.h>

#include <rkpm/contact/particle_to_segment.hpp>
#include <rkpm/solver/config.hpp>

#include "support/error_message.hpp"
#include "tools/runner/case_file/case_material.hpp"
#include "tools/runner/case_file/load_case_file.hpp"

namespace rkpm::test {

using case_json = runner::json;

// The plane-strain configuration the case-file tests run files with: the paper's method, the
// case files' material, effective-mass contact with Coulomb friction.
using plane_file_contact =
    contact::particle_to_segment<contact::enforcement::effective_mass, contact::friction::coulomb>;
using plane_file_config = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                                 runner::case_file::material_type, plane_file_contact>;

// cases/NAME.json of this repository (found from this header's own path).
inline std::filesystem::path paper_case_file(const std::string& name) {
  return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "cases" / (name + ".json");
}

inline case_json paper_case_document(const std::string& name) {
  std::ifstream in(paper_case_file(name));
  return case_json::parse(in, nullptr, true, true);
}

// A scratch folder for this program, removed at exit.
inline const std::filesystem::path& case_scratch() {
  struct folder {
    std::filesystem::path path = std::filesystem::temp_directory_path() / fmt::format("rkpm_case_file_{}", ::getpid());
    folder() { std::filesystem::create_directories(path); }
    ~folder() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const folder f;
  return f.path;
}

// Writes `text` to the scratch folder as `file_name` and returns its path.
inline std::filesystem::path write_case_text(const std::string& text, const std::string& file_name = "case.json") {
  const auto path = case_scratch() / file_name;
  std::ofstream(path) << text;
  return path;
}

inline runner::case_file::case_description load_document(const case_json& doc,
                                                         const runner::case_file::override_list& overrides = {}) {
  return runner::case_file::load_case_file(write_case_text(doc.dump(2)), overrides);
}

// The message of the error loading `doc` throws ("" if it loads).
inline std::string load_error(const case_json& doc, const runner::case_file::override_list& overrides = {}) {
  return error_message([&] { load_document(doc, overrides); });
}

// The message has a line for `pointer` in case.json that contains `fix`.
inline bool reports(const std::string& message, const std::string& pointer, const std::string& fix) {
  const std::string head = "case.json: " + pointer + ": ";
  for (std::size_t at = message.find(head); at != std::string::npos; at = message.find(head, at + 1)) {
    const std::string line = message.substr(at, message.find('\n', at) - at);
    if (contains(line, fix)) return true;
  }
  return false;
}

}  // namespace rkpm::test
