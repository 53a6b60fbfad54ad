#pragma once
// Helpers for tests of error messages: what rkpm::error a call throws, and whether it names a word.

#include <string>

#include <rkpm/core/error.hpp>

namespace rkpm::test {

// The message of the rkpm::error thrown by f, or "" if none was thrown.
template <class Fn>
std::string error_message(Fn&& f) {
  try {
    f();
  } catch (const rkpm::error& e) {
    return e.what();
  }
  return {};
}

inline bool contains(const std::string& text, const std::string& word) {
  return text.find(word) != std::string::npos;
}

}  // namespace rkpm::test
