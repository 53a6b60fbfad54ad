# FindLibdeflate: libdeflate (Debian libdeflate-dev), the whole-buffer DEFLATE compressor that
# writes rkpm's compressed VTK blocks when present (io/vtu_zlib.hpp). Used by the top
# CMakeLists.txt and installed next to rkpmConfig.cmake, which calls it for consumers.
#
# Defines Libdeflate_FOUND, Libdeflate_VERSION (when pkg-config knows it) and the imported
# target Libdeflate::Libdeflate. Debian's 1.14 ships no CMake config of its own (upstream does
# from 1.15), only libdeflate.pc, whose libdir is not the multiarch one; pkg-config gives
# hints, find_path/find_library decide.
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(PC_Libdeflate QUIET libdeflate)
endif()
find_path(Libdeflate_INCLUDE_DIR libdeflate.h HINTS ${PC_Libdeflate_INCLUDE_DIRS})
find_library(Libdeflate_LIBRARY NAMES deflate libdeflate HINTS ${PC_Libdeflate_LIBRARY_DIRS})
set(Libdeflate_VERSION ${PC_Libdeflate_VERSION})

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Libdeflate
  REQUIRED_VARS Libdeflate_LIBRARY Libdeflate_INCLUDE_DIR
  VERSION_VAR Libdeflate_VERSION)
mark_as_advanced(Libdeflate_INCLUDE_DIR Libdeflate_LIBRARY)

if(Libdeflate_FOUND AND NOT TARGET Libdeflate::Libdeflate)
  add_library(Libdeflate::Libdeflate UNKNOWN IMPORTED)
  set_target_properties(Libdeflate::Libdeflate PROPERTIES
    IMPORTED_LOCATION "${Libdeflate_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${Libdeflate_INCLUDE_DIR}")
endif()
