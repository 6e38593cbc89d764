# Debian's libp4est-dev ships no CMake config or pkg-config file: find the 3D header and the
# p4est and sc libraries by hand. P4EST_VERSION comes from p4est_config.h.
find_path(P4EST_INCLUDE_DIR p8est.h)
find_library(P4EST_LIBRARY NAMES p4est)
find_library(P4EST_SC_LIBRARY NAMES sc)
if(P4EST_INCLUDE_DIR AND EXISTS ${P4EST_INCLUDE_DIR}/p4est_config.h)
  file(STRINGS ${P4EST_INCLUDE_DIR}/p4est_config.h _p4est_version_line
       REGEX "^#define P4EST_VERSION \"[^\"]*\"")
  string(REGEX REPLACE ".*\"([^\"]*)\".*" "\\1" P4EST_VERSION "${_p4est_version_line}")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(P4EST REQUIRED_VARS P4EST_LIBRARY P4EST_SC_LIBRARY P4EST_INCLUDE_DIR
                                  VERSION_VAR P4EST_VERSION)
if(P4EST_FOUND AND NOT TARGET P4EST::P4EST)
  add_library(P4EST::SC UNKNOWN IMPORTED)
  set_target_properties(P4EST::SC PROPERTIES IMPORTED_LOCATION "${P4EST_SC_LIBRARY}")
  add_library(P4EST::P4EST UNKNOWN IMPORTED)
  set_target_properties(P4EST::P4EST PROPERTIES
    IMPORTED_LOCATION "${P4EST_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${P4EST_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES P4EST::SC)
endif()
mark_as_advanced(P4EST_INCLUDE_DIR P4EST_LIBRARY P4EST_SC_LIBRARY)
