#pragma once
// Edge topology of a PolyMesh, built on demand (cell → faces is build_cell_faces).
#include <array>
#include <span>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

struct MeshEdges {
  std::vector<std::array<Index, 2>> edges;  // unique, (a, b) with a < b, sorted
  // Face f's edges in loop order: edge k joins vertex k and k+1 of the face.
  std::vector<Index> face_edge_offsets;  // = mesh.face_offsets
  std::vector<Index> face_edges;
  std::span<const Index> of_face(Index f) const {
    return {face_edges.data() + face_edge_offsets[f],
            static_cast<std::size_t>(face_edge_offsets[f + 1] - face_edge_offsets[f])};
  }
};
MeshEdges build_edges(const PolyMesh& mesh);

// Point → cells using it, in CSR form with sorted, distinct cells per point.
struct PointCells {
  std::vector<Index> offsets;
  std::vector<Index> cells;
  std::span<const Index> of(Index p) const {
    return {cells.data() + offsets[p], static_cast<std::size_t>(offsets[p + 1] - offsets[p])};
  }
};
PointCells build_point_cells(const PolyMesh& mesh);

}  // namespace volmesh
