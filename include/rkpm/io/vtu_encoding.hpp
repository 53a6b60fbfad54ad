#pragma once
// How rkpm writes the DataArrays of a VTK XML file (used by io/vtk.hpp; docs/method.md section
// 9.4): the format options (encoding, compression) and the encoder that writes each array's
// XML and then the file, the raw appended block one array at a time (no array's bytes copied
// into one string, no more than one array's encoded block held). Arrays as VTK's own
// vtkXMLWriter writes them (header_type UInt64, native byte order); zlib compression
// (compressor="vtkZLibDataCompressor", blocks of 32 KiB compressed in parallel: io/vtu_zlib.hpp)
// when compiled with RKPM_WITH_LIBDEFLATE and linked with libdeflate, or with RKPM_WITH_ZLIB and
// linked with zlib; LZ4 compression (compressor="vtkLZ4DataCompressor", the same blocks:
// io/vtu_lz4.hpp) when compiled with RKPM_WITH_LZ4 and linked with liblz4.

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iterator>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>
#include <rkpm/io/vtu_lz4.hpp>
#include <rkpm/io/vtu_zlib.hpp>

namespace rkpm::io {

enum class vtu_encoding { appended, binary, ascii };
// zlib: the smallest files, read by every VTK reader (meshio too). lz4: about 8 times as fast
// to write and 15% larger, read by VTK 8.1 and later (ParaView 5.5 and later), not by meshio.
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
  // full-precision mantissas that no level finds matches in, so a higher level only spends time
  // (a snapshot of 10^6 particles, 201 MB of arrays: zlib 86.2 MB at 1, 85.4 MB at 6 in twice
  // the time; libdeflate 85.4 MB at 1, 85.6 MB at 6 in 2.3 times the time; tools/bench/vtu.cpp).
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
// io/vtu_zlib.hpp then the zlib streams of the 32 KiB blocks.
struct binary_block {
  std::vector<unsigned char> header;
  byte_buffer compressed;                 // the zlib blocks, when compressed
  std::span<const unsigned char> raw;     // the values, when not
  bool is_compressed = false;

  std::span<const unsigned char> body() const { return is_compressed ? std::span<const unsigned char>(compressed) : raw; }
  std::size_t size() const { return header.size() + body().size(); }
};

// Blocks [first, last) of bytes[0, size) compressed as `format` asks (compress_block_range of
// io/vtu_zlib.hpp with the format's library): their sizes into sizes[0 .. last-first), their
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
    append_u64(block.header, size);
    block.raw = std::span<const unsigned char>(bytes, size);
    return block;
  }
  block.is_compressed = true;
  std::vector<std::uint64_t> h = compression_header(size);
  std::vector<byte_buffer> part = compress_range(bytes, size, 0, h[0], format, name, h.data() + 3);
  block.header.resize(h.size() * sizeof(std::uint64_t));
  std::memcpy(block.header.data(), h.data(), block.header.size());
  // Joined in block order, the first piece taken as it is.
  std::size_t total = 0;
  for (const auto& p : part) total += p.size();
  block.compressed = std::move(part[0]);
  block.compressed.reserve(total);
  for (std::size_t k = 1; k < part.size(); ++k) block.compressed.insert(block.compressed.end(), part[k].begin(), part[k].end());
  return block;
}

// Blocks compressed and written at a time by write_appended: 4 MiB of raw bytes, so that an
// array's compressed bytes are never all held at once (35 MB for the stress of 10^6 particles).
inline constexpr std::size_t vtu_blocks_per_chunk = 128;

// Writes one appended DataArray's bytes as VTK reads them (the bytes of encode_binary's header
// and body) to `out` at its position, compressing vtu_blocks_per_chunk blocks at a time and
// writing each chunk before the next is made; the header, whose sizes are known only then, is
// written into the space left for it. Returns the bytes written.
inline std::size_t write_appended(std::ostream& out, const unsigned char* bytes, std::size_t size,
                                  const vtu_format& format, std::string_view name) {
  const auto put = [&out](const void* p, std::size_t n) {
    out.write(static_cast<const char*>(p), static_cast<std::streamsize>(n));
  };
  if (format.compression == vtu_compression::none) {
    const std::uint64_t count = size;
    put(&count, sizeof count);
    put(bytes, size);
    return sizeof count + size;
  }
  std::vector<std::uint64_t> h = compression_header(size);
  const std::streamoff start = out.tellp();
  put(h.data(), h.size() * sizeof(std::uint64_t));  // sizes still 0: rewritten below
  std::size_t written = h.size() * sizeof(std::uint64_t);
  for (std::size_t first = 0; first < h[0]; first += vtu_blocks_per_chunk) {
    const std::size_t last = std::min<std::size_t>(h[0], first + vtu_blocks_per_chunk);
    for (const byte_buffer& piece : compress_range(bytes, size, first, last, format, name, h.data() + 3 + first)) {
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

// Writes the XML of the DataArrays and then the file: one object per file. Appended arrays are
// encoded (compressed) only when the file is written, one after the other, each block written
// and let go before the next is made, so that a file never holds more than one array's block in
// memory; their offsets, known only then, go into space reserved for them in the XML.
class vtu_arrays {
 public:
  vtu_arrays(std::string& xml, const vtu_format& format) : xml_(xml), format_(format) {
    if (format_.encoding == vtu_encoding::ascii) format_.compression = vtu_compression::none;
  }

  // `tuples`: written as NumberOfTuples when given (the arrays of <FieldData> need it). The
  // values must live until write() has returned.
  template <class T>
  void add(std::string_view type, std::string_view name, int components, std::span<const T> values,
           std::size_t tuples = 0) {
    open_element(type, name, components, tuples);
    switch (format_.encoding) {
      case vtu_encoding::ascii:
        xml_ += " format=\"ascii\">";
        for (std::size_t i = 0; i < values.size(); ++i) {
          xml_ += (i % 9 == 0) ? "\n          " : " ";
          // uint8 would print as a character through fmt's char-like handling; widen it.
          if constexpr (sizeof(T) == 1)
            fmt::format_to(std::back_inserter(xml_), "{}", static_cast<int>(values[i]));
          else
            fmt::format_to(std::back_inserter(xml_), "{}", values[i]);
        }
        xml_ += "\n        </DataArray>\n";
        return;
      case vtu_encoding::binary: {
        const auto block = encode(values, name);
        xml_ += " format=\"binary\">\n          ";
        if (format_.compression == vtu_compression::none) {
          // One base64 stream of count and values, as vtkXMLWriter writes it uncompressed.
          std::vector<unsigned char> all(block.header);
          all.insert(all.end(), block.raw.begin(), block.raw.end());
          append_base64(xml_, all.data(), all.size());
        } else {
          // Compressed: header and blocks are two base64 streams.
          append_base64(xml_, block.header.data(), block.header.size());
          append_base64(xml_, block.compressed.data(), block.compressed.size());
        }
        xml_ += "\n        </DataArray>\n";
        return;
      }
      case vtu_encoding::appended:
        add_appended([this, values, name = std::string(name)](std::ostream& out) {
          return write_appended(out, reinterpret_cast<const unsigned char*>(values.data()), values.size_bytes(),
                                format_, name);
        });
        return;
    }
  }

  // The same with the values handed over: let go as soon as they are written (appended: when the
  // file reaches their block), so that the caller need not keep them.
  template <class T>
  void add_taken(std::string_view type, std::string_view name, int components, std::vector<T>&& values) {
    if (format_.encoding != vtu_encoding::appended) {  // encoded into the XML now, then let go
      const std::vector<T> taken = std::move(values);
      add(type, name, components, std::span<const T>(taken));
      return;
    }
    open_element(type, name, components, 0);
    add_appended([this, values = std::move(values), name = std::string(name)](std::ostream& out) mutable {
      const std::size_t n = write_appended(out, reinterpret_cast<const unsigned char*>(values.data()),
                                           values.size() * sizeof(T), format_, name);
      std::vector<T>().swap(values);
      return n;
    });
  }

  // A Float64 array whose values produce() makes: when its block is written (appended), else now.
  void add_produced(std::string_view name, int components, std::function<std::vector<double>()> produce) {
    if (format_.encoding != vtu_encoding::appended) {
      const std::vector<double> values = produce();
      add("Float64", name, components, std::span<const double>(values));
      return;
    }
    open_element("Float64", name, components, 0);
    add_appended([this, produce = std::move(produce), name = std::string(name)](std::ostream& out) {
      const std::vector<double> values = produce();
      return write_appended(out, reinterpret_cast<const unsigned char*>(values.data()),
                            values.size() * sizeof(double), format_, name);
    });
  }

  // After the last array and the closing </UnstructuredGrid>: writes the whole file, the XML, the
  // raw <AppendedData> block and `tail`, to `out` (a file open for writing in binary mode, which
  // is sought back into to fill in the offsets).
  // The arrays lie in the appended block in reverse order of the XML. Any order is valid VTK
  // (each array is read at its offset); this one is also read right by meshio 7, whose raw
  // reader rewrites the offsets in place while looking arrays up by offset in document order,
  // so that in document order a rewritten offset of an earlier array can equal the raw offset of
  // a later one and shadow it.
  void write(std::ostream& out, std::string_view tail) {
    if (format_.encoding != vtu_encoding::appended) {
      out << xml_ << tail;
      return;
    }
    // "_" marks offset 0; the newline after the last byte is not data.
    xml_ += "  <AppendedData encoding=\"raw\">\n   _";
    const std::streamoff head = out.tellp();
    out << xml_;
    const std::streamoff data = out.tellp();
    std::vector<std::uint64_t> offset(writers_.size());
    for (std::size_t k = writers_.size(); k-- > 0;) {
      offset[k] = static_cast<std::uint64_t>(out.tellp() - data);
      writers_[k](out);
    }
    out << "\n  </AppendedData>\n" << tail;
    const std::streamoff end = out.tellp();
    for (std::size_t k = 0; k < writers_.size(); ++k) {
      std::string value = fmt::format("{}\"", offset[k]);
      value.resize(reserved_offset_width, ' ');  // spaces before "/>" are nothing to a reader
      out.seekp(head + static_cast<std::streamoff>(marks_[k]));
      out << value;
    }
    out.seekp(end);
  }

  const vtu_format& format() const { return format_; }

 private:
  // Digits of any 64-bit offset and the closing quote.
  static constexpr std::size_t reserved_offset_width = 21;

  void open_element(std::string_view type, std::string_view name, int components, std::size_t tuples) {
    fmt::format_to(std::back_inserter(xml_), "        <DataArray type=\"{}\"", type);
    if (!name.empty()) fmt::format_to(std::back_inserter(xml_), " Name=\"{}\"", xml_escape(name));
    if (tuples > 0) fmt::format_to(std::back_inserter(xml_), " NumberOfTuples=\"{}\"", tuples);
    if (components > 1) fmt::format_to(std::back_inserter(xml_), " NumberOfComponents=\"{}\"", components);
  }
  void add_appended(std::function<std::size_t(std::ostream&)> writer) {
    xml_ += " format=\"appended\" offset=\"";
    marks_.push_back(xml_.size());  // the offset is written by write()
    xml_ += std::string(reserved_offset_width, ' ');
    xml_ += "/>\n";
    writers_.push_back(std::move(writer));
  }
  template <class T>
  binary_block encode(std::span<const T> values, std::string_view name) const {
    return encode_binary(reinterpret_cast<const unsigned char*>(values.data()), values.size_bytes(), format_,
                         name);
  }

  std::string& xml_;
  vtu_format format_;
  // appended: what writes each array's block (encoding it then), and where its offset goes in
  // xml_, in XML order
  std::vector<std::function<std::size_t(std::ostream&)>> writers_;
  std::vector<std::size_t> marks_;
};

}  // namespace detail

}  // namespace rkpm::io
