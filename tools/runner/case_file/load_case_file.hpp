#pragma once
// load_case_file(path, overrides): a case file read, overridden from the command line and
// checked in full before anything is built. Every mistake found is one line of the
// rkpm::error thrown: "FILE: POINTER: what is wrong; how to fix it". The file is JSON;
// // and /* */ comments are allowed, a field given twice in one object is an error.
//
// Phases, each reported in full before the next runs (so that a later check never trips
// over an earlier mistake): read and parse; overrides; every field on its own (read_case);
// mesh files (gmsh_bodies.hpp); checks across fields (cross_check).

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../json.hpp"
#include "case_description.hpp"
#include "cross_checks.hpp"
#include "diagnostics.hpp"
#include "gmsh_bodies.hpp"
#include "overrides.hpp"
#include "read_case.hpp"

namespace rkpm::runner::case_file {

namespace detail {

// Parses JSON text, reporting a syntax error with its line and column, and every field given
// twice in one object with its pointer (nlohmann would keep one silently).
inline json parse_case_text(const std::string& text, diagnostics& d) {
  struct level {
    bool array;
    std::string key;
    std::size_t index = 0;
    std::set<std::string> keys;
  };
  std::vector<level> stack;
  // The pointer of the field being read: the containers' keys and indices down to the top one.
  const auto pointer = [&] {
    std::string p;
    for (const level& l : stack) p = l.array ? child_pointer(p, l.index) : child_pointer(p, l.key);
    return p;
  };
  const auto next_element = [&] {
    if (!stack.empty() && stack.back().array) ++stack.back().index;
  };
  json::parser_callback_t callback = [&](int, json::parse_event_t event, json& parsed) {
    using e = json::parse_event_t;
    if (event == e::object_start || event == e::array_start) {
      stack.push_back({event == e::array_start, {}, 0, {}});
    } else if (event == e::key) {
      level& top = stack.back();
      top.key = parsed.get<std::string>();
      if (!top.keys.insert(top.key).second)
        d.error(pointer(), fmt::format("the field '{}' is given twice in this object; keep one", top.key));
    } else if (event == e::object_end || event == e::array_end) {
      stack.pop_back();
      next_element();
    } else {
      next_element();
    }
    return true;
  };
  try {
    return json::parse(text, callback, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    std::string what = e.what();
    if (const auto end = what.find("] "); end != std::string::npos) what.erase(0, end + 2);
    d.error_in_file(fmt::format("not valid JSON: {}; correct the syntax there", what));
    return json();
  }
}

}  // namespace detail

// The same from a document already parsed (a restart's, kept in its checkpoint); `file` names it
// in messages, and relative mesh paths are resolved against its folder. `resolution`: the one
// the problem will be built at, for .geo bodies, which are meshed here (gmsh_bodies.hpp).
inline case_description load_case_document(json document, const std::filesystem::path& file,
                                           const override_list& overrides = {}, int resolution = 1) {
  diagnostics d(file.string());
  apply_overrides(document, overrides, d);
  d.throw_if_any();
  case_description c = read_case(d, document, file);
  d.throw_if_any();
  read_meshes(d, c, resolution);
  d.throw_if_any();
  cross_check(d, c);
  d.throw_if_any();
  return c;
}

inline case_description load_case_file(const std::filesystem::path& path, const override_list& overrides = {},
                                       int resolution = 1) {
  diagnostics d(path.string());
  std::ifstream in(path, std::ios::binary);
  if (!std::filesystem::is_regular_file(path) || !in) {
    d.error_in_file(fmt::format("cannot read the case file ({}); give the path of a case file such as "
                                "cases/taylor_bar.json", std::filesystem::exists(path) ? "not a readable file"
                                                                                       : "no such file"));
    d.throw_if_any();
  }
  std::stringstream text;
  text << in.rdbuf();
  json document = detail::parse_case_text(text.str(), d);
  d.throw_if_any();
  return load_case_document(std::move(document), path, overrides, resolution);
}

}  // namespace rkpm::runner::case_file
