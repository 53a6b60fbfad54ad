// The module rkpm_gmsh_reader: the Gmsh reader of rkpm/io/gmsh_mesh.hpp behind the entry point
// that case_file/gmsh_reader.hpp loads with dlopen, so that only runs that mesh load libgmsh.
#include <rkpm/io/gmsh_mesh.hpp>

#include "case_file/gmsh_reader.hpp"

extern "C" __attribute__((visibility("default"))) const rkpm::runner::case_file::gmsh_reader* rkpm_gmsh_reader() {
  static const rkpm::runner::case_file::gmsh_reader reader{
      [](const std::filesystem::path& msh_file, double support_factor) {
        return rkpm::io::read_gmsh_body(msh_file, support_factor);
      },
      [](const std::filesystem::path& geo_file, double size_factor, double support_factor) {
        return rkpm::io::mesh_geo_file(geo_file, size_factor, support_factor);
      },
      [](const std::vector<rkpm::vec2>& vertices, double spacing, double support_factor) {
        return rkpm::io::mesh_polygon(vertices, spacing, support_factor);
      },
  };
  return &reader;
}
