#pragma once
// Per-hex access shared by the hexdc tests of meshes after contouring.
#include <array>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh::test_hexdc {

inline std::array<Vec3, 8> corners_of(const HexMesh& mesh, std::size_t h) {
  std::array<Vec3, 8> corners;
  for (std::size_t c = 0; c < 8; ++c) corners[c] = mesh.points[mesh.cells[h][c]];
  return corners;
}

}  // namespace volmesh::test_hexdc
