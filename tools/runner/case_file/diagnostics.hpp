#pragma once
// diagnostics: the errors found in one case file, collected so that a user sees every mistake
// of a file at once, each on one line "FILE: POINTER: what is wrong; how to fix it", where
// POINTER is the JSON pointer (RFC 6901) of the offending field. closest_choice suggests the
// known name nearest to a misspelt one.

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>

namespace rkpm::runner::case_file {

class diagnostics {
 public:
  explicit diagnostics(std::string file) : file_(std::move(file)) {}

  // message: "what is wrong; how to fix it". An empty pointer is the whole document.
  void error(std::string_view pointer, std::string_view message) {
    lines_.push_back(fmt::format("{}: {}: {}", file_, pointer.empty() ? "(top level)" : pointer, message));
  }
  // For errors that belong to no field (the file cannot be read or parsed).
  void error_in_file(std::string_view message) { lines_.push_back(fmt::format("{}: {}", file_, message)); }

  bool empty() const { return lines_.empty(); }
  const std::vector<std::string>& lines() const { return lines_; }
  const std::string& file() const { return file_; }

  // Throws rkpm::error with every line collected, in the order found.
  void throw_if_any() const {
    if (lines_.empty()) return;
    std::string text;
    for (const auto& l : lines_) text += (text.empty() ? "" : "\n") + l;
    throw rkpm::error(text);
  }

 private:
  std::string file_;
  std::vector<std::string> lines_;
};

// Throws the one line "FILE: POINTER: message", for a mistake found after loading (building).
[[noreturn]] inline void fail_in_file(const std::string& file, std::string_view pointer, std::string_view message) {
  diagnostics d(file);
  d.error(pointer, message);
  d.throw_if_any();
  throw rkpm::error(std::string(message));  // not reached
}

// "/bodies/0" + "material" -> "/bodies/0/material", escaping '~' and '/' as RFC 6901 says.
inline std::string child_pointer(std::string_view parent, std::string_view key) {
  std::string out(parent);
  out += '/';
  for (char c : key) out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
  return out;
}
inline std::string child_pointer(std::string_view parent, std::size_t index) {
  return fmt::format("{}/{}", parent, index);
}

// Levenshtein distance, ignoring case (a user typing "youngs_modulus_pa" meant the _Pa one).
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      const std::size_t next = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = row[j];
      row[j] = next;
    }
  }
  return row[b.size()];
}

// The choice nearest to `word`, if it is near enough to be a misspelling (a third of the
// word's length, at least 2 edits) or contains it ("modulus" -> "youngs_modulus_Pa").
template <class Choices>
std::optional<std::string> closest_choice(std::string_view word, const Choices& choices) {
  std::optional<std::string> best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : choices) {
    const std::string_view choice(c);
    std::size_t d = edit_distance(word, choice);
    if (d >= best_distance && word.size() >= 4 && choice.find(word) != std::string_view::npos) d = best_distance - 1;
    if (d < best_distance) {
      best_distance = d;
      best = std::string(choice);
    }
  }
  return best;
}

// "a, b, c"
template <class Choices>
std::string list_choices(const Choices& choices) {
  std::string out;
  for (const auto& c : choices) out += fmt::format("{}{}", out.empty() ? "" : ", ", std::string_view(c));
  return out;
}

// "did you mean 'b'? (the choices are: a, b, c)" or "the choices are: a, b, c".
template <class Choices>
std::string suggest(std::string_view word, const Choices& choices, std::string_view what = "the choices are") {
  const auto best = closest_choice(word, choices);
  if (best) return fmt::format("did you mean '{}'? ({}: {})", *best, what, list_choices(choices));
  return fmt::format("{}: {}", what, list_choices(choices));
}

}  // namespace rkpm::runner::case_file
