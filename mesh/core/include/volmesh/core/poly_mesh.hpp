#pragma once
// Face-based polyhedral mesh, laid out like OpenFOAM's polyMesh (docs/architecture.md).
#include <span>
#include <string>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh {

// Faces are vertex loops stored in CSR arrays and oriented so that their right-hand normal
// points from owner to neighbour (outward from the owner). A boundary face has
// neighbour == kNoIndex and a boundary tag >= 0; an internal face has tag kNoIndex.
// Region 0 is reserved for "outside"; cells carry regions >= 1.
struct PolyMesh {
  std::vector<Vec3> points;
  std::vector<Index> face_offsets{0};  // face f: face_vertices[face_offsets[f], face_offsets[f+1])
  std::vector<Index> face_vertices;
  std::vector<Index> owner;
  std::vector<Index> neighbour;
  std::vector<Index> face_tag;
  std::vector<Index> cell_region;
  std::vector<std::string> tag_names;  // name of each boundary tag (patch)

  Index num_points() const { return static_cast<Index>(points.size()); }
  Index num_faces() const { return static_cast<Index>(owner.size()); }
  Index num_cells() const { return static_cast<Index>(cell_region.size()); }
  bool is_boundary(Index f) const { return neighbour[f] == kNoIndex; }

  std::span<const Index> face(Index f) const {
    return {face_vertices.data() + face_offsets[f],
            static_cast<std::size_t>(face_offsets[f + 1] - face_offsets[f])};
  }

  // Appends a face; returns its index. Boundary faces (neighbour == kNoIndex) need a tag.
  Index add_face(std::span<const Index> vertices, Index owner_cell, Index neighbour_cell,
                 Index tag = kNoIndex);

  // Room for this many more faces with this many vertices in all, so that add_face does not
  // regrow the arrays.
  void reserve_faces(std::size_t faces, std::size_t vertices);

  // Index of the tag with this name, created if missing.
  Index tag_index(const std::string& name);
};

// Per-cell list of faces in CSR form, built on demand.
struct CellFaces {
  std::vector<Index> offsets;  // size num_cells + 1
  std::vector<Index> faces;
  std::span<const Index> of(Index c) const {
    return {faces.data() + offsets[c], static_cast<std::size_t>(offsets[c + 1] - offsets[c])};
  }
};
CellFaces build_cell_faces(const PolyMesh& mesh);

// Sign with which face f enters cell c's outward orientation: +1 for owner, -1 for neighbour.
inline int face_sign(const PolyMesh& mesh, Index f, Index c) { return mesh.owner[f] == c ? 1 : -1; }

// Sorted distinct region labels present in the mesh.
std::vector<Index> regions_of(const PolyMesh& mesh);

}  // namespace volmesh
