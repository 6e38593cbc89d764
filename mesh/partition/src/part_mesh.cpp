#include "volmesh/partition/part_mesh.hpp"

#include <algorithm>

#include "volmesh/core/cell_soup.hpp"

namespace volmesh {

std::string part_boundary_name(Index part, Index other) {
  return "procBoundary" + std::to_string(part) + "to" + std::to_string(other);
}

namespace {

// Faces of part p in face order: its cells' faces, once each.
std::vector<std::vector<Index>> faces_by_part(const PolyMesh& mesh,
                                              std::span<const Index> cell_part, Index parts) {
  std::vector<std::vector<Index>> faces(parts);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Index p = cell_part[mesh.owner[f]];
    faces[p].push_back(f);
    if (!mesh.is_boundary(f) && cell_part[mesh.neighbour[f]] != p)
      faces[cell_part[mesh.neighbour[f]]].push_back(f);
  }
  return faces;
}

// Fills part.mesh's faces and points; local_cell maps global cells to their part's numbering,
// local_point is all kNoIndex on entry and on exit.
void build_part(const PolyMesh& mesh, std::span<const Index> cell_part, Index p,
                const std::vector<Index>& faces, const std::vector<Index>& local_cell,
                std::vector<Index>& local_point, PartMesh& part) {
  for (Index f : faces)
    for (Index v : mesh.face(f))
      if (local_point[v] == kNoIndex) {
        local_point[v] = 0;
        part.global_points.push_back(v);
      }
  std::sort(part.global_points.begin(), part.global_points.end());
  for (std::size_t i = 0; i < part.global_points.size(); ++i) {
    local_point[part.global_points[i]] = static_cast<Index>(i);
    part.mesh.points.push_back(mesh.points[part.global_points[i]]);
  }

  // Tags: the mesh's own, then one per neighbouring part in increasing order.
  part.mesh.tag_names = mesh.tag_names;
  std::vector<Index> others;
  for (Index f : faces)
    if (!mesh.is_boundary(f))
      for (Index c : {mesh.owner[f], mesh.neighbour[f]})
        if (cell_part[c] != p) others.push_back(cell_part[c]);
  std::sort(others.begin(), others.end());
  others.erase(std::unique(others.begin(), others.end()), others.end());
  for (Index q : others) part.mesh.tag_index(part_boundary_name(p, q));

  std::vector<Index> loop;
  for (Index f : faces) {
    loop.clear();
    for (Index v : mesh.face(f)) loop.push_back(local_point[v]);
    const Index o = mesh.owner[f], n = mesh.neighbour[f];
    if (mesh.is_boundary(f)) {
      part.mesh.add_face(loop, local_cell[o], kNoIndex, mesh.face_tag[f]);
    } else if (cell_part[o] == p && cell_part[n] == p) {
      part.mesh.add_face(loop, local_cell[o], local_cell[n]);
    } else if (cell_part[o] == p) {
      part.mesh.add_face(loop, local_cell[o], kNoIndex,
                         part.mesh.tag_index(part_boundary_name(p, cell_part[n])));
    } else {  // this part's cell is the neighbour: turn the face outward from it
      std::reverse(loop.begin(), loop.end());
      part.mesh.add_face(loop, local_cell[n], kNoIndex,
                         part.mesh.tag_index(part_boundary_name(p, cell_part[o])));
    }
  }
  for (Index v : part.global_points) local_point[v] = kNoIndex;
  drop_unused_tags(part.mesh);
}

}  // namespace

std::vector<PartMesh> split_mesh(const PolyMesh& mesh, std::span<const Index> cell_part,
                                 Index parts) {
  std::vector<PartMesh> result(parts);
  for (Index c = 0; c < mesh.num_cells(); ++c) result[cell_part[c]].global_cells.push_back(c);
  std::vector<Index> local_cell(mesh.num_cells());
  for (PartMesh& part : result) {
    for (std::size_t i = 0; i < part.global_cells.size(); ++i) {
      local_cell[part.global_cells[i]] = static_cast<Index>(i);
      part.mesh.cell_region.push_back(mesh.cell_region[part.global_cells[i]]);
    }
  }
  const std::vector<std::vector<Index>> faces = faces_by_part(mesh, cell_part, parts);
  std::vector<Index> local_point(mesh.num_points(), kNoIndex);
  for (Index p = 0; p < parts; ++p)
    build_part(mesh, cell_part, p, faces[p], local_cell, local_point, result[p]);
  return result;
}

}  // namespace volmesh
