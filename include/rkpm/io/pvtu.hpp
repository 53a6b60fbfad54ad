#pragma once
// write_pvtu: the index of one snapshot written in pieces, one .vtu per process (docs/method.md
// section 9.4): a PUnstructuredGrid that declares the pieces' points and point arrays (name,
// Float64, components, as write_vtu writes them: io/vtk.hpp) and names each piece's file,
// relative to the index. ParaView reads the index and loads the pieces as one data set; each
// piece is a complete .vtu that any reader opens alone. The pieces need not hold disjoint
// points (a process may write ghost nodes of the cells it writes); GhostLevel is 0. Written
// whole or not at all (io/files.hpp replace_file), after the pieces, so an index never names a
// piece that is not there.

#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>
#include <rkpm/io/files.hpp>
#include <rkpm/io/point_data.hpp>
#include <rkpm/io/vtu_encoding.hpp>

namespace rkpm::io {

// The piece of `rank` for the index `pvtu`: beside it, "<stem>_<rank>.vtu" (snapshot_0007.pvtu
// -> snapshot_0007_2.vtu).
inline std::filesystem::path pvtu_piece(const std::filesystem::path& pvtu, int rank) {
  return pvtu.parent_path() / fmt::format("{}_{}.vtu", pvtu.stem().string(), rank);
}

// pieces: the pieces' files (each named relative to the index's folder when it lies there);
// arrays: the point arrays every piece holds, in their order (their values are not read).
inline void write_pvtu(const std::filesystem::path& path, const std::vector<std::filesystem::path>& pieces,
                       const point_data& arrays) {
  if (pieces.empty()) fail("write_pvtu '{}': no pieces; give one .vtu per process", path.string());
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "  <PUnstructuredGrid GhostLevel=\"0\">\n"
      "    <PPointData>\n";
  for (const point_data::array& a : arrays.arrays())
    xml += fmt::format("      <PDataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\"/>\n",
                       detail::xml_escape(a.name), a.components);
  xml +=
      "    </PPointData>\n"
      "    <PPoints>\n"
      "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
      "    </PPoints>\n";
  const std::filesystem::path folder = path.parent_path();
  for (const std::filesystem::path& piece : pieces) {
    const std::filesystem::path source = piece.parent_path() == folder ? piece.filename() : piece;
    xml += fmt::format("    <Piece Source=\"{}\"/>\n", detail::xml_escape(source.string()));
  }
  xml +=
      "  </PUnstructuredGrid>\n"
      "</VTKFile>\n";
  replace_file(path, xml);
}

}  // namespace rkpm::io
