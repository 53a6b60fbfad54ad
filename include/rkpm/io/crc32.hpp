#pragma once
// crc32_of: the CRC-32 of zlib, gzip and PNG (reflected polynomial 0xEDB88320) of any number of
// bytes, continuing `crc` (0 to start). zlib's crc32_z when compiled with RKPM_WITH_ZLIB (it
// reads several bytes at a time); otherwise a bytewise table, a few times slower, with
// the same values, so a file checked by one build reads in the other. Checkpoints use it
// (io/checkpoint_format.hpp): it finds every error of up to 32 consecutive bits in a block.

#include <array>
#include <cstddef>
#include <cstdint>

#ifdef RKPM_WITH_ZLIB
#include <zlib.h>
#endif

namespace rkpm::io {

inline std::uint32_t crc32_portable(const void* data, std::size_t n, std::uint32_t crc = 0) {
  static constexpr auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  const auto* p = static_cast<const unsigned char*>(data);
  crc = ~crc;
  for (std::size_t i = 0; i < n; ++i) crc = table[(crc ^ p[i]) & 0xffu] ^ (crc >> 8);
  return ~crc;
}

inline std::uint32_t crc32_of(const void* data, std::size_t n, std::uint32_t crc = 0) {
#ifdef RKPM_WITH_ZLIB
  return static_cast<std::uint32_t>(::crc32_z(crc, static_cast<const Bytef*>(data), n));
#else
  return crc32_portable(data, n, crc);
#endif
}

}  // namespace rkpm::io
