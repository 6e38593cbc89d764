#include "volmesh/core/poly_mesh.hpp"

#include <algorithm>

namespace volmesh {

Index PolyMesh::add_face(std::span<const Index> vertices, Index owner_cell, Index neighbour_cell,
                         Index tag) {
  face_vertices.insert(face_vertices.end(), vertices.begin(), vertices.end());
  face_offsets.push_back(static_cast<Index>(face_vertices.size()));
  owner.push_back(owner_cell);
  neighbour.push_back(neighbour_cell);
  face_tag.push_back(tag);
  return static_cast<Index>(owner.size()) - 1;
}

void PolyMesh::reserve_faces(std::size_t faces, std::size_t vertices) {
  face_offsets.reserve(face_offsets.size() + faces);
  face_vertices.reserve(face_vertices.size() + vertices);
  owner.reserve(owner.size() + faces);
  neighbour.reserve(neighbour.size() + faces);
  face_tag.reserve(face_tag.size() + faces);
}

Index PolyMesh::tag_index(const std::string& name) {
  auto it = std::find(tag_names.begin(), tag_names.end(), name);
  if (it != tag_names.end()) return static_cast<Index>(it - tag_names.begin());
  tag_names.push_back(name);
  return static_cast<Index>(tag_names.size()) - 1;
}

CellFaces build_cell_faces(const PolyMesh& mesh) {
  const Index nc = mesh.num_cells();
  CellFaces cf;
  cf.offsets.assign(nc + 1, 0);
  auto count = [&](Index c) {
    if (c >= 0 && c < nc) ++cf.offsets[c + 1];
  };
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    count(mesh.owner[f]);
    count(mesh.neighbour[f]);
  }
  for (Index c = 0; c < nc; ++c) cf.offsets[c + 1] += cf.offsets[c];
  cf.faces.resize(cf.offsets[nc]);
  std::vector<Index> fill(cf.offsets.begin(), cf.offsets.end() - 1);
  // Faces are visited in increasing order, so each cell's list is sorted.
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    for (Index c : {mesh.owner[f], mesh.neighbour[f]})
      if (c >= 0 && c < nc) cf.faces[fill[c]++] = f;
  }
  return cf;
}

std::vector<Index> regions_of(const PolyMesh& mesh) {
  std::vector<Index> r = mesh.cell_region;
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  return r;
}

}  // namespace volmesh
