#pragma once
// zlib compression of one VTK binary DataArray (io/vtu_encoding.hpp, docs/method.md section
// 9.4), as vtkZLibDataCompressor lays it out: the bytes cut into blocks of 32 KiB, each its own
// zlib stream, behind the UInt64 header [#blocks, block size, size of a partial last block (0
// if none), compressed size of each block].
//
// Two libraries write the streams, both in the zlib format any zlib inflate (VTK's, Python's)
// reads, with different bytes: libdeflate (RKPM_WITH_LIBDEFLATE, Debian libdeflate-dev) when
// the build found it, about twice as fast for a whole block in memory, which is all a block is
// here; else zlib (RKPM_WITH_ZLIB). vtu_format::deflater picks one at run time.
//
// The blocks are compressed in parallel (OpenMP threads, each a contiguous run of blocks).
// Every block is compressed alone, by a compressor whose output depends only on the block and
// the level (zlib: deflateReset gives the state of a fresh deflateInit, i.e. compress2();
// libdeflate: no state is kept between calls), so the bytes are those of a serial writer,
// whatever the thread count. Each thread has its compressor and a buffer of its own; the
// buffers are then joined in thread, hence block, order.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif
#ifdef RKPM_WITH_ZLIB
#include <zlib.h>
#endif
#ifdef RKPM_WITH_LIBDEFLATE
#include <libdeflate.h>
#endif

#include <rkpm/core/error.hpp>

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
// smaller (README, "Performance notes").
inline constexpr vtu_deflater default_vtu_deflater =
    vtu_libdeflate_available ? vtu_deflater::libdeflate : vtu_deflater::zlib;
inline constexpr bool vtu_deflater_available(vtu_deflater d) {
  return d == vtu_deflater::libdeflate ? vtu_libdeflate_available : vtu_zlib_library_available;
}

}  // namespace rkpm::io

namespace rkpm::io::detail {

inline constexpr std::size_t vtu_block_size = 32768;

// A byte vector whose resize() leaves the new bytes uninitialised. Each thread's buffer is sized
// for the worst case (a little more than the raw bytes) and the compressors fill less than half
// of it on a solver's data: zeroing it first would write and fault in pages never used.
template <class T>
struct uninitialized_allocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = uninitialized_allocator<U>;
  };
  using std::allocator<T>::allocator;
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... A>
  void construct(U* p, A&&... a) {
    ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
  }
};
using byte_buffer = std::vector<unsigned char, uninitialized_allocator<unsigned char>>;

inline void append_u64(std::vector<unsigned char>& out, std::uint64_t v) {
  unsigned char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  out.insert(out.end(), b, b + sizeof v);
}

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

// Compresses blocks [first, last) of bytes[0, size), each by a Deflater (one per thread) at
// `level`: their compressed sizes into sizes[0 .. last-first), their bytes into the returned
// pieces, to be taken in order (one per thread, each a contiguous run of the blocks).
template <class Deflater>
std::vector<byte_buffer> compress_block_range(const unsigned char* bytes, std::size_t size, std::size_t first_block,
                                              std::size_t last_block, int level, std::string_view name,
                                              std::uint64_t* sizes) {
  const std::size_t blocks = last_block - first_block;
  int threads = 1;
#ifdef _OPENMP
  // A thread per ~8 blocks at least: a small array is not worth waking threads for.
  threads = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(omp_get_max_threads()),
                                                   std::max<std::size_t>(1, blocks / 8)));
#endif
  std::vector<byte_buffer> part(static_cast<std::size_t>(threads));
  std::size_t failed = blocks;  // the first block any thread failed to compress
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    int t = 0, team = 1;
#ifdef _OPENMP
    t = omp_get_thread_num();
    team = omp_get_num_threads();
#endif
    // This thread's blocks: first .. last-1 of the range, contiguous, in thread order.
    const std::size_t first = blocks * static_cast<std::size_t>(t) / static_cast<std::size_t>(team);
    const std::size_t last = blocks * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(team);
    byte_buffer& out = part[static_cast<std::size_t>(t)];
    std::optional<Deflater> deflater;
    if (first < last) deflater.emplace(level);
    std::size_t at = 0, bad = blocks;
    for (std::size_t b = first; b < last && bad == blocks; ++b) {
      const std::size_t begin = (first_block + b) * vtu_block_size, n = std::min(vtu_block_size, size - begin);
      const std::size_t room = deflater->bound(n);
      // Room for all of this thread's blocks at once, grown only if a bound is exceeded.
      if (b == first) out.resize(room * (last - first));
      if (out.size() < at + room) out.resize(at + room);
      const std::size_t c = deflater->compress(bytes + begin, n, out.data() + at, room);
      if (c == 0) bad = b;
      sizes[b] = c;
      at += c;
    }
    out.resize(at);
    if (bad != blocks) {
#pragma omp critical(rkpm_vtu_zlib)
      failed = std::min(failed, bad);
    }
  }
  if (failed != blocks)
    fail("write_vtu: compression failed (block {}) on array \"{}\"; try vtu_compression::none", first_block + failed,
         name);
  return part;
}

// VTK's compression header of `size` bytes: [#blocks, block size, size of a partial last block
// (0 if none), one compressed size per block (0 until known)].
inline std::vector<std::uint64_t> compression_header(std::size_t size) {
  const std::size_t blocks = (size + vtu_block_size - 1) / vtu_block_size;
  std::vector<std::uint64_t> h(3 + blocks, 0);
  h[0] = blocks;
  h[1] = vtu_block_size;
  h[2] = size % vtu_block_size;
  return h;
}

}  // namespace rkpm::io::detail
