# FindLZ4: liblz4 (Debian liblz4-dev), which writes rkpm's LZ4-compressed VTK blocks when present
# (io/vtu_lz4.hpp). Used by the top CMakeLists.txt and installed next to rkpmConfig.cmake, which
# calls it for consumers.
#
# Defines LZ4_FOUND, LZ4_VERSION (when pkg-config knows it) and the imported target LZ4::LZ4.
# Debian's 1.9.4 ships liblz4.pc but no CMake config; pkg-config gives hints, find_path and
# find_library decide.
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(PC_LZ4 QUIET liblz4)
endif()
find_path(LZ4_INCLUDE_DIR lz4.h HINTS ${PC_LZ4_INCLUDE_DIRS})
find_library(LZ4_LIBRARY NAMES lz4 liblz4 HINTS ${PC_LZ4_LIBRARY_DIRS})
set(LZ4_VERSION ${PC_LZ4_VERSION})

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(LZ4
  REQUIRED_VARS LZ4_LIBRARY LZ4_INCLUDE_DIR
  VERSION_VAR LZ4_VERSION)
mark_as_advanced(LZ4_INCLUDE_DIR LZ4_LIBRARY)

if(LZ4_FOUND AND NOT TARGET LZ4::LZ4)
  add_library(LZ4::LZ4 UNKNOWN IMPORTED)
  set_target_properties(LZ4::LZ4 PROPERTIES
    IMPORTED_LOCATION "${LZ4_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${LZ4_INCLUDE_DIR}")
endif()
