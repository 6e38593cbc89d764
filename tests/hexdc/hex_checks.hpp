#pragma once
// Per-hex access shared by the hexdc tests of meshes after contouring.
#include <array>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/hexdc/hex_quality.hpp"

namespace volmesh::test_hexdc {

inline std::array<Vec3, 8> corners_of(const HexMesh& mesh, std::size_t h) {
  std::array<Vec3, 8> corners;
  for (std::size_t c = 0; c < 8; ++c) corners[c] = mesh.points[mesh.cells[h][c]];
  return corners;
}

// Hexes failing the ten corner tets.
inline Index invalid_hexes(const HexMesh& mesh) {
  Index n = 0;
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    n += hex_corner_tets_positive(corners_of(mesh, h)) ? 0 : 1;
  return n;
}

}  // namespace volmesh::test_hexdc
