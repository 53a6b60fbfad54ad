#pragma once
// zlib compression of the blocks of a VTK binary DataArray (io/vtu_blocks.hpp), as
// vtkZLibDataCompressor writes them: each block its own zlib stream.
//
// Two libraries write the streams, both in the zlib format any zlib inflate (VTK's, Python's)
// reads, with different bytes: libdeflate (RKPM_WITH_LIBDEFLATE, Debian libdeflate-dev) when
// the build found it, about twice as fast for a whole block in memory, which is all a block is
// here; else zlib (RKPM_WITH_ZLIB). vtu_format::deflater picks one at run time. Neither keeps
// state from one block to the next (zlib: deflateReset gives the state of a fresh deflateInit,
// i.e. compress2(); libdeflate: no state is kept between calls).

#include <cstddef>

#ifdef RKPM_WITH_ZLIB
#include <zlib.h>
#endif
#ifdef RKPM_WITH_LIBDEFLATE
#include <libdeflate.h>
#endif

#include <rkpm/io/vtu_blocks.hpp>

namespace rkpm::io {

// The library that writes the zlib streams (same format, different bytes).
enum class vtu_deflater { zlib, libdeflate };

// Which libraries this translation unit can write zlib streams with (RKPM_WITH_LIBDEFLATE and
// libdeflate, RKPM_WITH_ZLIB and zlib); vtu_zlib_available: either, the format is the same.
#ifdef RKPM_WITH_LIBDEFLATE
inline constexpr bool vtu_libdeflate_available = true;
#else
inline constexpr bool vtu_libdeflate_available = false;
#endif
#ifdef RKPM_WITH_ZLIB
inline constexpr bool vtu_zlib_library_available = true;
#else
inline constexpr bool vtu_zlib_library_available = false;
#endif
inline constexpr bool vtu_zlib_available = vtu_libdeflate_available || vtu_zlib_library_available;
// libdeflate when compiled in: the same level takes about half zlib's time for a file a little
// smaller (docs/performance.md, "Writing a snapshot"; tools/rkpm bench --vtu).
inline constexpr vtu_deflater default_vtu_deflater =
    vtu_libdeflate_available ? vtu_deflater::libdeflate : vtu_deflater::zlib;
inline constexpr bool vtu_deflater_available(vtu_deflater d) {
  return d == vtu_deflater::libdeflate ? vtu_libdeflate_available : vtu_zlib_library_available;
}

}  // namespace rkpm::io

namespace rkpm::io::detail {

// One thread's compressor of single blocks, each a whole zlib stream: bound(n) is the room
// compress() may need for n bytes; compress() returns the stream's size, 0 on failure.
#ifdef RKPM_WITH_ZLIB
class zlib_block_deflater {
 public:
  explicit zlib_block_deflater(int level) : ok_(deflateInit(&zs_, level) == Z_OK) {}
  ~zlib_block_deflater() { if (ok_) deflateEnd(&zs_); }
  zlib_block_deflater(const zlib_block_deflater&) = delete;
  zlib_block_deflater& operator=(const zlib_block_deflater&) = delete;

  static std::size_t bound(std::size_t n) { return compressBound(static_cast<uLong>(n)); }
  std::size_t compress(const unsigned char* in, std::size_t n, unsigned char* out, std::size_t room) {
    if (!ok_ || deflateReset(&zs_) != Z_OK) return 0;
    zs_.next_in = const_cast<Bytef*>(in);  // zlib's API is not const; it only reads
    zs_.avail_in = static_cast<uInt>(n);
    zs_.next_out = out;
    zs_.avail_out = static_cast<uInt>(room);
    return deflate(&zs_, Z_FINISH) == Z_STREAM_END ? static_cast<std::size_t>(zs_.total_out) : 0;
  }

 private:
  z_stream zs_{};
  bool ok_;
};
#endif

#ifdef RKPM_WITH_LIBDEFLATE
class libdeflate_block_deflater {
 public:
  explicit libdeflate_block_deflater(int level) : c_(libdeflate_alloc_compressor(level)) {}
  ~libdeflate_block_deflater() { libdeflate_free_compressor(c_); }  // null: nothing to free
  libdeflate_block_deflater(const libdeflate_block_deflater&) = delete;
  libdeflate_block_deflater& operator=(const libdeflate_block_deflater&) = delete;

  // A null compressor (allocation failed) gives the bound of any compressor.
  std::size_t bound(std::size_t n) const { return libdeflate_zlib_compress_bound(c_, n); }
  std::size_t compress(const unsigned char* in, std::size_t n, unsigned char* out, std::size_t room) {
    return c_ ? libdeflate_zlib_compress(c_, in, n, out, room) : 0;
  }

 private:
  libdeflate_compressor* c_;
};
#endif

}  // namespace rkpm::io::detail
