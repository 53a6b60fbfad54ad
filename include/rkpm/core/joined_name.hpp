#pragma once
// joined_name<a, b, ...>::value: the compile-time string "a+b+..." of policy names, so that a
// composed policy (j2_plasticity<linear>, particle_to_segment<paper, coulomb>) has a name that
// tells its parts apart, as a static constexpr std::string_view like every other policy's.

#include <array>
#include <cstddef>
#include <string_view>

namespace rkpm {

template <const std::string_view&... Parts>
struct joined_name {
 private:
  static constexpr std::size_t length = (Parts.size() + ...) + sizeof...(Parts) - 1;
  static constexpr std::array<char, length + 1> storage = [] {
    std::array<char, length + 1> text{};
    std::size_t at = 0;
    bool first = true;
    auto append = [&](std::string_view part) {
      if (!first) text[at++] = '+';
      first = false;
      for (char c : part) text[at++] = c;
    };
    (append(Parts), ...);
    return text;
  }();

 public:
  static constexpr std::string_view value{storage.data(), length};
};

}  // namespace rkpm
