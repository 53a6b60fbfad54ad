#pragma once
// The runner's Gmsh functions (rkpm/io/gmsh_mesh.hpp), loaded with dlopen when a case file first
// names a mesh or a polygon, from the module rkpm_gmsh_reader (tools/runner/gmsh_reader_module.cpp),
// the one part of the runner linked with libgmsh. Linked into rkpm_run itself, Gmsh's hundred or
// so shared libraries cost every run about 48 MB of resident memory before it read anything (the
// dynamic loader's relocations and symbol tables; docs/performance.md), 47 B per particle at 10^6.
// The module is found at RKPM_GMSH_READER (environment) if set, else where the build put it
// (RKPM_GMSH_READER_MODULE, defined by tools/runner/CMakeLists.txt).

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <rkpm/core/error.hpp>
#include <rkpm/core/types.hpp>
#include <rkpm/io/gmsh_body.hpp>

#ifndef RKPM_GMSH_READER_MODULE
#define RKPM_GMSH_READER_MODULE "librkpm_gmsh_reader.so"
#endif

namespace rkpm::runner::case_file {

// What the module hands over: io::read_gmsh_body, io::mesh_geo_file and io::mesh_polygon.
struct gmsh_reader {
  io::gmsh_body (*read_msh)(const std::filesystem::path& msh_file, double support_factor);
  io::gmsh_body (*mesh_geo)(const std::filesystem::path& geo_file, double size_factor, double support_factor);
  io::gmsh_body (*mesh_polygon)(const std::vector<vec2>& vertices, double spacing, double support_factor);
};

// The module's entry point, extern "C" so that dlsym finds it by this name.
inline constexpr const char* gmsh_reader_entry = "rkpm_gmsh_reader";

// The reader, loaded on the first call (never unloaded: its functions stay in use).
inline const gmsh_reader& load_gmsh_reader() {
  static const gmsh_reader* const reader = [] {
    const char* const from_environment = std::getenv("RKPM_GMSH_READER");
    const std::string path = from_environment && *from_environment ? from_environment : RKPM_GMSH_READER_MODULE;
    void* const module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module)
      fail("Gmsh meshes need the runner's Gmsh reader, which could not be loaded ({}): build the target "
           "rkpm_gmsh_reader (tools/rkpm run builds it with the runner), or set RKPM_GMSH_READER to its path",
           dlerror());
    using entry = const gmsh_reader* (*)();
    const auto get = reinterpret_cast<entry>(dlsym(module, gmsh_reader_entry));
    if (!get)
      fail("{} is not the runner's Gmsh reader (no function {}): set RKPM_GMSH_READER to the rkpm_gmsh_reader "
           "module of this build",
           path, gmsh_reader_entry);
    return get();
  }();
  return *reader;
}

}  // namespace rkpm::runner::case_file
