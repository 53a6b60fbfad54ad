#pragma once
// rkpm::error: the one exception type of the library. Messages name the problem and, where
// there is one, the fix ("support 0 in direction 1 must be positive: give a_i > 0").

#include <fmt/format.h>
#include <stdexcept>
#include <string>
#include <utility>

namespace rkpm {

class error : public std::runtime_error {
 public:
  explicit error(const std::string& what) : std::runtime_error(what) {}
};

// Throws rkpm::error with a fmt-formatted message.
template <class... Args>
[[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) {
  throw error(fmt::format(format, std::forward<Args>(args)...));
}

}  // namespace rkpm
