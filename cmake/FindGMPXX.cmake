# GMP and its C++ bindings (gmpxx), used by the exact rational tet mesher. Named GMPXX so
# that it does not shadow the FindGMP module CGAL ships and relies on.
find_path(GMPXX_INCLUDE_DIR gmpxx.h)
find_library(GMPXX_GMP_LIBRARY NAMES gmp)
find_library(GMPXX_LIBRARY NAMES gmpxx)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(GMPXX REQUIRED_VARS GMPXX_GMP_LIBRARY GMPXX_LIBRARY GMPXX_INCLUDE_DIR)
if(GMPXX_FOUND AND NOT TARGET GMP::GMP)
  add_library(GMP::GMP UNKNOWN IMPORTED)
  set_target_properties(GMP::GMP PROPERTIES
    IMPORTED_LOCATION "${GMPXX_GMP_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${GMPXX_INCLUDE_DIR}")
  add_library(GMP::GMPXX UNKNOWN IMPORTED)
  set_target_properties(GMP::GMPXX PROPERTIES
    IMPORTED_LOCATION "${GMPXX_LIBRARY}"
    INTERFACE_LINK_LIBRARIES GMP::GMP)
endif()
mark_as_advanced(GMPXX_INCLUDE_DIR GMPXX_GMP_LIBRARY GMPXX_LIBRARY)
