#pragma once
// vtu_arrays: the DataArrays of one VTK XML file (io/vtk.hpp; docs/method.md section 9.4) as the
// writer adds them, their XML written at once and, for appended data, each array's block encoded
// (io/vtu_encoding.hpp) only when the file is written.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/io/point_data.hpp>
#include <rkpm/io/vtu_encoding.hpp>

namespace rkpm::io::detail {

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

  // An array of `count` values of T made piecewise: prepare() returns fill(first, n, out), which
  // writes values first .. first + n - 1 to out. Appended, prepare() runs when the file reaches
  // the array's block and fill() a chunk at a time (write_appended_chunks), so that neither the
  // raw array nor its compressed bytes are held whole; otherwise the array is made now.
  template <class T>
  void add_filled(std::string_view type, std::string_view name, int components, std::size_t count,
                  std::function<value_filler<T>()> prepare) {
    if (format_.encoding != vtu_encoding::appended) {
      const std::vector<T> values = filled_values(count, prepare);
      add(type, name, components, std::span<const T>(values));
      return;
    }
    open_element(type, name, components, 0);
    add_appended([this, count, prepare = std::move(prepare), name = std::string(name)](std::ostream& out) {
      const value_filler<T> fill = prepare();
      std::vector<T> chunk;
      return write_appended_chunks(out, count * sizeof(T), format_, name, [&](std::size_t first, std::size_t n) {
        chunk.resize(n / sizeof(T));  // chunks start and end on whole values (blocks of 32 KiB)
        fill(first / sizeof(T), chunk.size(), chunk.data());
        return reinterpret_cast<const unsigned char*>(chunk.data());
      });
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

}  // namespace rkpm::io::detail
