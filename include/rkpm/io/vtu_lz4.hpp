#pragma once
// LZ4 compression of one VTK binary DataArray (io/vtu_encoding.hpp, docs/method.md section
// 9.4), as vtkLZ4DataCompressor writes it (VTK 8.1 and later, so ParaView 5.5 and later): the
// block layout of io/vtu_blocks.hpp (32 KiB blocks behind the UInt64 header [#blocks, block size,
// size of a partial last block, compressed size of each block]), each block a raw LZ4 block
// (LZ4_compress_default, no frame and no size prefix: the reader knows the block's size from
// the header).
//
// LZ4 trades size for time: on a solver's doubles it compresses several times as fast as zlib
// at level 1 and gives a larger file (tools/rkpm bench --vtu compares them). It is compiled in with
// RKPM_WITH_LZ4 and liblz4 (Debian liblz4-dev), which the rkpm CMake target does when it finds
// them. meshio 1.x does not read it; ParaView and VTK's own readers do.

#include <algorithm>
#include <cstddef>
#include <limits>

#ifdef RKPM_WITH_LZ4
#include <lz4.h>
#endif

#include <rkpm/io/vtu_blocks.hpp>

namespace rkpm::io {

#ifdef RKPM_WITH_LZ4
inline constexpr bool vtu_lz4_available = true;
#else
inline constexpr bool vtu_lz4_available = false;
#endif

}  // namespace rkpm::io

namespace rkpm::io::detail {

#ifdef RKPM_WITH_LZ4
// One thread's compressor of single blocks (the Deflater of compress_block_range): no state
// between blocks, so the bytes do not depend on the thread count. `level` is not used: LZ4's
// default acceleration, as vtkLZ4DataCompressor's.
class lz4_block_compressor {
 public:
  explicit lz4_block_compressor(int /*level*/) {}

  static std::size_t bound(std::size_t n) { return static_cast<std::size_t>(LZ4_compressBound(static_cast<int>(n))); }
  static std::size_t compress(const unsigned char* in, std::size_t n, unsigned char* out, std::size_t room) {
    // A block is 32 KiB, far below int's range; room is capped for the same reason.
    const int c = LZ4_compress_default(reinterpret_cast<const char*>(in), reinterpret_cast<char*>(out),
                                       static_cast<int>(n),
                                       static_cast<int>(std::min<std::size_t>(room, std::numeric_limits<int>::max())));
    return c > 0 ? static_cast<std::size_t>(c) : 0;
  }
};
#endif

}  // namespace rkpm::io::detail
