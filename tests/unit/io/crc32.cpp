// rkpm::io::crc32_of (io/crc32.hpp), the checksum of checkpoints: the standard CRC-32 check
// value, continuation over pieces, and the bytewise table (builds without zlib) giving zlib's
// values, so that a checkpoint written by one build reads in the other.
#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <string>

#include <rkpm/io/crc32.hpp>

namespace test_unit_io_crc32 {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

TEST_CASE("crc32: the CRC-32 of zlib, whole or in pieces, with or without zlib") {
  using rkpm::io::crc32_of;
  using rkpm::io::crc32_portable;
  const std::string check = "123456789";
  CHECK(crc32_of(check.data(), check.size()) == 0xCBF43926u);  // the CRC-32 check value
  CHECK(crc32_portable(check.data(), check.size()) == 0xCBF43926u);
  CHECK(crc32_of(check.data(), 0) == 0u);

  std::mt19937_64 random(7);
  std::string bytes(100003, '\0');
  for (char& c : bytes) c = static_cast<char>(random());
  const std::uint32_t whole = crc32_of(bytes.data(), bytes.size());
  CHECK(crc32_portable(bytes.data(), bytes.size()) == whole);
  CHECK(crc32_of(bytes.data() + 4097, bytes.size() - 4097, crc32_of(bytes.data(), 4097)) == whole);
  CHECK(crc32_portable(bytes.data() + 5, bytes.size() - 5, crc32_portable(bytes.data(), 5)) == whole);
  bytes[50000] ^= 1;
  CHECK(crc32_of(bytes.data(), bytes.size()) != whole);
}

}  // namespace test_unit_io_crc32
