# Precompiled headers for cold builds (VOLMESH_PCH): the headers nearly every translation unit
# parses, compiled once per group of targets whose flags match, by an empty target of the
# group's own that links only what the headers need (GCC refuses a precompiled header built
# with a macro the user lacks, such as TBB's TBB_USE_DEBUG in Debug), the others reusing it.
# Groups: the test programs (GoogleTest added), the targets compiled with CGAL's flags
# (-frounding-math), the rest.
# CGAL's own headers stay out: the few files that include them gain less than the others,
# which would load them too, lose. Off by default: a precompiled header differs byte for byte
# from one build tree to the next, so ccache cannot share the objects that use it between trees.

set(VOLMESH_PCH_COMMON <algorithm> <array> <cmath> <cstdint> <functional> <limits> <map>
  <memory> <optional> <span> <stdexcept> <string> <string_view> <utility> <vector>
  <Eigen/Core> <Eigen/Geometry>)
set(VOLMESH_PCH_EXTRA_tests <gtest/gtest.h>)
set(VOLMESH_PCH_LINK_plain Eigen3::Eigen)
set(VOLMESH_PCH_LINK_cgal Eigen3::Eigen CGAL::CGAL)
set(VOLMESH_PCH_LINK_tests Eigen3::Eigen GTest::gtest)

# The C++ targets defined in dir and below.
function(_volmesh_cxx_targets dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  set(result)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(type MATCHES "^(STATIC_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$")
      list(APPEND result ${target})
    endif()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(subdir IN LISTS subdirs)
    _volmesh_cxx_targets(${subdir} below)
    list(APPEND result ${below})
  endforeach()
  set(${out} ${result} PARENT_SCOPE)
endfunction()

# Gives every C++ target of the project a precompiled header; call after all targets exist.
function(volmesh_precompile_headers)
  _volmesh_cxx_targets(${PROJECT_SOURCE_DIR} targets)
  foreach(target IN LISTS targets)
    get_target_property(source_dir ${target} SOURCE_DIR)
    get_target_property(links ${target} LINK_LIBRARIES)
    if(source_dir MATCHES "^${PROJECT_SOURCE_DIR}/tests(/|$)")
      set(group tests)
    elseif("CGAL::CGAL" IN_LIST links)
      set(group cgal)
    else()
      set(group plain)
    endif()
    set(owner volmesh_pch_${group})
    if(NOT TARGET ${owner})
      set(source ${PROJECT_BINARY_DIR}/${owner}.cpp)
      file(CONFIGURE OUTPUT ${source} CONTENT "")
      add_library(${owner} OBJECT EXCLUDE_FROM_ALL ${source})
      target_link_libraries(${owner} PRIVATE ${VOLMESH_PCH_LINK_${group}})
      target_precompile_headers(${owner} PRIVATE ${VOLMESH_PCH_COMMON} ${VOLMESH_PCH_EXTRA_${group}})
    endif()
    target_precompile_headers(${target} REUSE_FROM ${owner})
  endforeach()
endfunction()
