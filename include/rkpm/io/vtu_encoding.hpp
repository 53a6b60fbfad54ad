#pragma once
// How rkpm encodes the DataArrays of a VTK XML file (io/vtu_arrays.hpp writes them; docs/method.md
// section 9.4): the format options (encoding, compression), the text helpers (XML escapes,
// base64) and the encoders of one array's bytes: whole (inline base64) or written to the file a
// chunk of blocks at a time (appended). Arrays as VTK's own vtkXMLWriter writes them
// (header_type UInt64, native byte order); zlib compression (compressor="vtkZLibDataCompressor",
// blocks of 32 KiB compressed in parallel: io/vtu_blocks.hpp, io/vtu_zlib.hpp)
// when compiled with RKPM_WITH_LIBDEFLATE and linked with libdeflate, or with RKPM_WITH_ZLIB and
// linked with zlib; LZ4 compression (compressor="vtkLZ4DataCompressor", the same blocks:
// io/vtu_lz4.hpp) when compiled with RKPM_WITH_LZ4 and linked with liblz4.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/io/vtu_lz4.hpp>
#include <rkpm/io/vtu_zlib.hpp>

namespace rkpm::io {

enum class vtu_encoding { appended, binary, ascii };
// zlib: the smallest files, read by every VTK reader (meshio too), hence the default. lz4: much
// faster to write, larger files, read by VTK 8.1 and later (ParaView 5.5 and later), not by
// meshio (tools/rkpm bench --vtu compares them).
enum class vtu_compression { none, zlib, lz4 };

inline constexpr std::string_view vtu_compression_name(vtu_compression c) {
  return c == vtu_compression::zlib ? "zlib" : c == vtu_compression::lz4 ? "lz4" : "none";
}
// The compressor attribute of <VTKFile> (empty: uncompressed).
inline constexpr std::string_view vtu_compressor_attribute(vtu_compression c) {
  return c == vtu_compression::zlib ? "vtkZLibDataCompressor" : c == vtu_compression::lz4 ? "vtkLZ4DataCompressor" : "";
}

// zlib when this translation unit can write it (io/vtu_zlib.hpp: libdeflate or zlib).
inline constexpr vtu_compression default_vtu_compression =
    vtu_zlib_available ? vtu_compression::zlib : vtu_compression::none;

// How a .vtu is written; converts from a bare encoding, so write_vtu(path, x, d,
// vtu_encoding::ascii) still reads as before. Compression applies to appended and binary data.
struct vtu_format {
  vtu_encoding encoding = vtu_encoding::appended;
  vtu_compression compression = default_vtu_compression;
  // 1 (fastest) .. 9 (smallest). 1, not zlib's default 6: a solver's doubles have
  // full-precision mantissas in which no level finds matches, so a higher level spends about
  // twice the time for a file hardly smaller (tools/rkpm bench --vtu shows both levels).
  int zlib_level = 1;
  vtu_deflater deflater = default_vtu_deflater;  // who writes the streams at that level

  vtu_format() = default;
  vtu_format(vtu_encoding e, vtu_compression c = default_vtu_compression) : encoding(e), compression(c) {}  // NOLINT
};

namespace detail {

inline std::string xml_escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

inline void append_base64(std::string& out, const unsigned char* bytes, std::size_t n) {
  static constexpr char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::size_t i = 0;
  for (; i + 3 <= n; i += 3) {
    const std::uint32_t w = (std::uint32_t{bytes[i]} << 16) | (std::uint32_t{bytes[i + 1]} << 8) | bytes[i + 2];
    out += table[(w >> 18) & 63];
    out += table[(w >> 12) & 63];
    out += table[(w >> 6) & 63];
    out += table[w & 63];
  }
  if (const std::size_t rest = n - i; rest > 0) {
    std::uint32_t w = std::uint32_t{bytes[i]} << 16;
    if (rest == 2) w |= std::uint32_t{bytes[i + 1]} << 8;
    out += table[(w >> 18) & 63];
    out += table[(w >> 12) & 63];
    out += rest == 2 ? table[(w >> 6) & 63] : '=';
    out += '=';
  }
}

// Bytes of one binary DataArray as VTK reads them: uncompressed, a UInt64 byte count then the
// values (a view of the caller's array, not a copy); compressed, the UInt64 header of
// io/vtu_blocks.hpp then the compressed 32 KiB blocks.
struct binary_block {
  std::vector<unsigned char> header;
  byte_buffer compressed;                 // the zlib blocks, when compressed
  std::span<const unsigned char> raw;     // the values, when not
  bool is_compressed = false;

  std::span<const unsigned char> body() const { return is_compressed ? std::span<const unsigned char>(compressed) : raw; }
  std::size_t size() const { return header.size() + body().size(); }
};

// Blocks [first, last) of bytes[0, size) compressed as `format` asks (compress_block_range of
// io/vtu_blocks.hpp with the format's library): their sizes into sizes[0 .. last-first), their
// bytes as pieces to be taken in order.
inline std::vector<byte_buffer> compress_range(const unsigned char* bytes, std::size_t size, std::size_t first,
                                               std::size_t last, const vtu_format& format, std::string_view name,
                                               std::uint64_t* sizes) {
  if (format.compression == vtu_compression::lz4) {
#ifdef RKPM_WITH_LZ4
    return compress_block_range<lz4_block_compressor>(bytes, size, first, last, 0, name, sizes);
#else
    fail("write_vtu: array \"{}\": LZ4 compression asked for, but rkpm was compiled without it; install "
         "liblz4-dev and reconfigure (or compile with -DRKPM_WITH_LZ4 and link -llz4), or use "
         "vtu_compression::zlib", name);
#endif
  }
#ifdef RKPM_WITH_LIBDEFLATE
  if (format.deflater == vtu_deflater::libdeflate)
    return compress_block_range<libdeflate_block_deflater>(bytes, size, first, last, format.zlib_level, name, sizes);
#endif
#ifdef RKPM_WITH_ZLIB
  if (format.deflater == vtu_deflater::zlib)
    return compress_block_range<zlib_block_deflater>(bytes, size, first, last, format.zlib_level, name, sizes);
#endif
  fail("write_vtu: array \"{}\": zlib compression by {} asked for, but rkpm was compiled without it; "
       "install libdeflate-dev or zlib1g-dev and reconfigure (or compile with -DRKPM_WITH_LIBDEFLATE "
       "and link -ldeflate, -DRKPM_WITH_ZLIB and -lz), or use vtu_compression::none", name,
       format.deflater == vtu_deflater::zlib ? "zlib" : "libdeflate");
}

inline binary_block encode_binary(const unsigned char* bytes, std::size_t size, const vtu_format& format,
                                  std::string_view name) {
  binary_block block;
  if (format.compression == vtu_compression::none) {
    block.header = header_bytes({size});
    block.raw = std::span<const unsigned char>(bytes, size);
    return block;
  }
  block.is_compressed = true;
  std::vector<std::uint64_t> h = compression_header(size);
  std::vector<byte_buffer> part = compress_range(bytes, size, 0, h[0], format, name, h.data() + 3);
  block.header = header_bytes(h);
  // Joined in block order, the first piece taken as it is.
  std::size_t total = 0;
  for (const auto& p : part) total += p.size();
  block.compressed = std::move(part[0]);
  block.compressed.reserve(total);
  for (std::size_t k = 1; k < part.size(); ++k) block.compressed.insert(block.compressed.end(), part[k].begin(), part[k].end());
  return block;
}

// Blocks compressed and written at a time by write_appended: 4 MiB of raw bytes, so that an
// array's compressed bytes are never all held at once (35 MB for the stress of 10^6 particles),
// nor, for an array made piecewise (vtu_arrays::add_filled), its raw bytes.
inline constexpr std::size_t vtu_blocks_per_chunk = 128;

// Writes one appended DataArray of `size` bytes as VTK reads them (the bytes of encode_binary's
// header and body) to `out` at its position, vtu_blocks_per_chunk blocks at a time: chunk(first,
// n) gives the array's bytes first .. first + n - 1 (valid until the next call), each chunk is
// compressed and written before the next is asked for, and the header, whose sizes are known
// only then, is written into the space left for it. Returns the bytes written.
template <class Chunk>
std::size_t write_appended_chunks(std::ostream& out, std::size_t size, const vtu_format& format,
                                  std::string_view name, Chunk&& chunk) {
  const auto put = [&out](const void* p, std::size_t n) {
    out.write(static_cast<const char*>(p), static_cast<std::streamsize>(n));
  };
  constexpr std::size_t chunk_bytes = vtu_blocks_per_chunk * vtu_block_size;
  if (format.compression == vtu_compression::none) {
    const std::uint64_t count = size;
    put(&count, sizeof count);
    for (std::size_t first = 0; first < size; first += chunk_bytes) {
      const std::size_t n = std::min(chunk_bytes, size - first);
      put(chunk(first, n), n);
    }
    return sizeof count + size;
  }
  std::vector<std::uint64_t> h = compression_header(size);
  const std::streamoff start = out.tellp();
  put(h.data(), h.size() * sizeof(std::uint64_t));  // sizes still 0: rewritten below
  std::size_t written = h.size() * sizeof(std::uint64_t);
  for (std::size_t first = 0; first < h[0]; first += vtu_blocks_per_chunk) {
    // The chunk's blocks are the array's blocks first .. last - 1: each compressed alone.
    const std::size_t last = std::min<std::size_t>(h[0], first + vtu_blocks_per_chunk);
    const std::size_t begin = first * vtu_block_size, n = std::min(size, last * vtu_block_size) - begin;
    for (const byte_buffer& piece : compress_range(chunk(begin, n), n, 0, last - first, format, name, h.data() + 3 + first)) {
      put(piece.data(), piece.size());
      written += piece.size();
    }
  }
  const std::streamoff end = out.tellp();
  out.seekp(start);
  put(h.data(), h.size() * sizeof(std::uint64_t));
  out.seekp(end);
  return written;
}

// The same from the whole array's bytes.
inline std::size_t write_appended(std::ostream& out, const unsigned char* bytes, std::size_t size,
                                  const vtu_format& format, std::string_view name) {
  return write_appended_chunks(out, size, format, name, [bytes](std::size_t first, std::size_t) { return bytes + first; });
}

}  // namespace detail

}  // namespace rkpm::io
