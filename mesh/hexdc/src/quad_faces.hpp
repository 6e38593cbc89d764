#pragma once
// Hex faces looked up by their nodes, whatever their order and orientation (pillowing).
#include <algorithm>
#include <array>
#include <map>
#include <vector>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh::hexdc_detail {

using QuadKey = std::array<Index, 4>;

inline QuadKey sorted_key(std::array<Index, 4> quad) {
  std::sort(quad.begin(), quad.end());
  return quad;
}

inline QuadKey hex_face_key(const HexMesh& mesh, Index h, const std::array<int, 4>& face) {
  const auto& cell = mesh.cells[static_cast<std::size_t>(h)];
  return sorted_key({cell[face[0]], cell[face[1]], cell[face[2]], cell[face[3]]});
}

// Each boundary quad's hex: the one having a face on the quad's four nodes (-1 if none).
inline std::vector<Index> quad_owners(const HexMesh& mesh) {
  std::map<QuadKey, Index> index;
  for (std::size_t q = 0; q < mesh.boundary_faces.size(); ++q)
    index.emplace(sorted_key(mesh.boundary_faces[q]), static_cast<Index>(q));
  std::vector<Index> owner(mesh.boundary_faces.size(), -1);
  for (Index h = 0; h < mesh.num_cells(); ++h)
    for (const auto& face : kHexFaces) {
      const auto it = index.find(hex_face_key(mesh, h, face));
      if (it != index.end()) owner[static_cast<std::size_t>(it->second)] = h;
    }
  return owner;
}

}  // namespace volmesh::hexdc_detail
