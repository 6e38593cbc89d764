#pragma once
// Conversions between element meshes and PolyMesh, and recognition of element shapes
// inside a PolyMesh.
#include <array>
#include <optional>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// Builds the face-based mesh; shared faces are matched by their vertex sets. Boundary faces
// take the tag of the matching element boundary face, or a tag named "boundary" if none.
PolyMesh to_poly_mesh(const TetMesh& mesh);
PolyMesh to_poly_mesh(const HexMesh& mesh);

enum class CellShape { Tetrahedron, Hexahedron, Polyhedron };

// The shape of cell c and, for tets and hexes, its corners in VTK order.
struct CellCorners {
  CellShape shape = CellShape::Polyhedron;
  std::array<Index, 8> corners{};
};
CellCorners classify_cell(const PolyMesh& mesh, const CellFaces& cell_faces, Index c);

// Throws std::runtime_error naming the first cell that is not a tet (hex).
TetMesh to_tet_mesh(const PolyMesh& mesh);
HexMesh to_hex_mesh(const PolyMesh& mesh);

}  // namespace volmesh
