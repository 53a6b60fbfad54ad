#pragma once
// Command-line overrides of a case file, `--set /bodies/0/material/yield_stress_Pa=3e8`: a JSON
// pointer (RFC 6901) to a field the file has, and a value text read as JSON ("3e8", "[0, -1]",
// "null", "true"), or as a string when it is not JSON ("q4"). The overridden document is
// then checked like any file, so a value of the wrong kind is reported at its pointer.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "../json.hpp"
#include "diagnostics.hpp"
#include "json_fields.hpp"

namespace rkpm::runner::case_file {

// (JSON pointer, value text) pairs, in command-line order.
using override_list = std::vector<std::pair<std::string, std::string>>;

inline json override_value(const std::string& text) {
  try {
    return json::parse(text);
  } catch (const json::parse_error&) {
    return text;
  }
}

namespace detail {

// "/a~1b/0" -> {"a/b", "0"} (the pointer starts with '/').
inline std::vector<std::string> pointer_tokens(std::string_view pointer) {
  std::vector<std::string> tokens;
  std::string token;
  for (std::size_t i = 1; i < pointer.size(); ++i) {
    const char c = pointer[i];
    if (c == '/') {
      tokens.push_back(std::move(token));
      token.clear();
    } else if (c == '~' && i + 1 < pointer.size() && (pointer[i + 1] == '0' || pointer[i + 1] == '1')) {
      token += pointer[++i] == '0' ? '~' : '/';
    } else {
      token += c;
    }
  }
  tokens.push_back(std::move(token));
  return tokens;
}

// The field the pointer names, or nullptr after reporting where the walk stopped and what was
// there instead.
inline json* resolve(json& document, const std::string& pointer, diagnostics& d) {
  const std::string where = "--set " + pointer;
  if (pointer.empty() || pointer[0] != '/') {
    d.error(where, "a field is named by a JSON pointer starting with '/'; give e.g. "
                   "--set /bodies/0/material/yield_stress_Pa=3e8");
    return nullptr;
  }
  json* node = &document;
  std::string reached;
  for (const std::string& token : pointer_tokens(pointer)) {
    const std::string shown = reached.empty() ? "the top level" : reached;
    if (node->is_object()) {
      const auto it = node->find(token);
      if (it == node->end()) {
        std::vector<std::string> keys;
        for (const auto& [k, _] : node->items()) keys.push_back(k);
        d.error(where, fmt::format("{} has no field '{}'; {}", shown, token, suggest(token, keys, "its fields are")));
        return nullptr;
      }
      node = &*it;
      reached = child_pointer(reached, token);
    } else if (node->is_array()) {
      const bool digits = !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
      if (!digits || token.size() > 9 || std::stoul(token) >= node->size()) {
        d.error(where, fmt::format("{} is a list of {} entries; give an index from 0 to {} in place of '{}'", shown,
                                   node->size(), node->size() == 0 ? 0 : node->size() - 1, token));
        return nullptr;
      }
      node = &(*node)[std::stoul(token)];
      reached = child_pointer(reached, token);
    } else {
      d.error(where, fmt::format("{} is {} and has no field '{}'; set {} itself", shown, describe(*node), token,
                                 shown));
      return nullptr;
    }
  }
  return node;
}

}  // namespace detail

// Applies the overrides in order (a later one wins), reporting each that names no field.
inline void apply_overrides(json& document, const override_list& overrides, diagnostics& d) {
  for (const auto& [pointer, text] : overrides)
    if (json* field = detail::resolve(document, pointer, d)) *field = override_value(text);
}

}  // namespace rkpm::runner::case_file
