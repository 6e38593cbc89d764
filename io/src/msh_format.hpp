#pragma once
// Names and numbers of Gmsh's MSH 4.1 format shared by the writer and the reader.
#include <string>

#include "volmesh/core/types.hpp"

namespace volmesh::msh {

// Gmsh element types (first-order elements only).
inline constexpr int kTriangle = 2;
inline constexpr int kQuadrangle = 3;
inline constexpr int kTetrahedron = 4;
inline constexpr int kHexahedron = 5;
inline constexpr int kPrism = 6;
inline constexpr int kPyramid = 7;

// Volume physical group (and entity) r holds the cells of region r.
inline std::string region_name(Index region) { return "region_" + std::to_string(region); }

// Surface physical group of the internal faces between regions a < b.
inline std::string interface_name(Index a, Index b) {
  return "interface_" + std::to_string(a) + "_" + std::to_string(b);
}

}  // namespace volmesh::msh
