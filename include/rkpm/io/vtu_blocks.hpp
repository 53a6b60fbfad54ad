#pragma once
// The block layout of a compressed VTK binary DataArray (io/vtu_encoding.hpp, docs/method.md
// section 9.4), as VTK's compressors (vtkZLibDataCompressor, vtkLZ4DataCompressor) lay it out: the
// bytes cut into blocks of 32 KiB, each compressed alone, behind the UInt64 header [#blocks,
// block size, size of a partial last block (0 if none), compressed size of each block].
//
// compress_block_range compresses a run of blocks in parallel (OpenMP threads, each a contiguous
// run of blocks) with any per-block compressor (io/vtu_zlib.hpp: zlib and libdeflate;
// io/vtu_lz4.hpp: LZ4). Every block is compressed alone, by a compressor whose output depends
// only on the block and the level, so the bytes are those of a serial writer, whatever the thread
// count. Each thread has its compressor and a buffer of its own, taken in thread, hence block,
// order.

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

#include <rkpm/core/error.hpp>

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

// Header words as the bytes a file holds (native byte order, as the XML declares).
inline std::vector<unsigned char> header_bytes(const std::vector<std::uint64_t>& words) {
  std::vector<unsigned char> out(words.size() * sizeof(std::uint64_t));
  std::memcpy(out.data(), words.data(), out.size());
  return out;
}

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
