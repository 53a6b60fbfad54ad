#pragma once
// zlib compression of one VTK binary DataArray (io/vtu_encoding.hpp, docs/method.md section
// 9.4), as vtkZLibDataCompressor lays it out: the bytes cut into blocks of 32 KiB, each its own
// zlib stream, behind the UInt64 header [#blocks, block size, size of a partial last block (0
// if none), compressed size of each block].
//
// The blocks are compressed in parallel (OpenMP threads, each a contiguous run of blocks).
// Every block is compressed alone, from a fresh stream with the parameters of zlib's
// compress2() (deflateInit(level): window 2^15, memory level 8, default strategy), so the bytes
// are those of a serial compress2() per block, whatever the thread count. Each thread keeps one
// z_stream and resets it per block (deflateReset gives the state of a fresh deflateInit) and
// writes into a buffer of its own; the buffers are then joined in thread, hence block, order.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif
#ifdef RKPM_WITH_ZLIB
#include <zlib.h>
#endif

#include <rkpm/core/error.hpp>

namespace rkpm::io::detail {

inline constexpr std::size_t vtu_block_size = 32768;

inline void append_u64(std::vector<unsigned char>& out, std::uint64_t v) {
  unsigned char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  out.insert(out.end(), b, b + sizeof v);
}

#ifdef RKPM_WITH_ZLIB
// Appends to `header` the block header and to `body` the compressed blocks of bytes[0, size).
inline void compress_vtu_blocks(const unsigned char* bytes, std::size_t size, int level, std::string_view name,
                                std::vector<unsigned char>& header, std::vector<unsigned char>& body) {
  const std::size_t blocks = (size + vtu_block_size - 1) / vtu_block_size;
  std::vector<std::uint64_t> compressed(blocks, 0);
  int threads = 1;
#ifdef _OPENMP
  // A thread per ~8 blocks at least: a small array is not worth waking threads for.
  threads = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(omp_get_max_threads()),
                                                   std::max<std::size_t>(1, blocks / 8)));
#endif
  std::vector<std::vector<unsigned char>> part(static_cast<std::size_t>(threads));
  int failure = Z_OK;  // the first zlib error of any thread
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    int t = 0, team = 1;
#ifdef _OPENMP
    t = omp_get_thread_num();
    team = omp_get_num_threads();
#endif
    // This thread's blocks: first .. last-1, contiguous, in thread order.
    const std::size_t first = blocks * static_cast<std::size_t>(t) / static_cast<std::size_t>(team);
    const std::size_t last = blocks * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(team);
    std::vector<unsigned char>& out = part[static_cast<std::size_t>(t)];
    z_stream zs{};
    int rc = first < last ? deflateInit(&zs, level) : Z_OK;
    if (first < last && rc == Z_OK) {
      const std::size_t in_bytes = std::min(size, last * vtu_block_size) - first * vtu_block_size;
      out.resize(compressBound(static_cast<uLong>(in_bytes)) + (last - first) * 16);
      std::size_t at = 0;
      for (std::size_t b = first; b < last && rc == Z_OK; ++b) {
        const std::size_t begin = b * vtu_block_size, n = std::min(vtu_block_size, size - begin);
        const std::size_t room = compressBound(static_cast<uLong>(n));
        if (out.size() < at + room) out.resize(at + room);
        rc = deflateReset(&zs);
        zs.next_in = const_cast<Bytef*>(bytes + begin);  // zlib's API is not const; it only reads
        zs.avail_in = static_cast<uInt>(n);
        zs.next_out = out.data() + at;
        zs.avail_out = static_cast<uInt>(room);
        if (rc == Z_OK) rc = deflate(&zs, Z_FINISH) == Z_STREAM_END ? Z_OK : Z_BUF_ERROR;
        compressed[b] = zs.total_out;
        at += zs.total_out;
      }
      out.resize(at);
    }
    if (first < last) deflateEnd(&zs);
    if (rc != Z_OK) {
#pragma omp critical(rkpm_vtu_zlib)
      if (failure == Z_OK) failure = rc;
    }
  }
  if (failure != Z_OK)
    fail("write_vtu: zlib failed ({}) on array \"{}\"; try vtu_compression::none", failure, name);
  append_u64(header, blocks);
  append_u64(header, vtu_block_size);
  append_u64(header, size % vtu_block_size);
  for (const std::uint64_t c : compressed) append_u64(header, c);
  // Joined in block order; the first thread's buffer is taken as it is when `body` is empty.
  std::size_t total = body.size();
  for (const auto& p : part) total += p.size();
  std::size_t from = 0;
  if (body.empty()) body = std::move(part[from++]);
  body.reserve(total);
  for (; from < part.size(); ++from) body.insert(body.end(), part[from].begin(), part[from].end());
}
#endif

}  // namespace rkpm::io::detail
