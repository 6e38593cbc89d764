#include "volmesh/core/convert.hpp"

#include <algorithm>
#include <string>

#include "volmesh/core/cell_soup.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh {

namespace {

template <class Mesh>
PolyMesh element_to_poly(const Mesh& mesh, LinearCell kind) {
  CellSoup soup("mesh");
  soup.points = mesh.points;
  soup.tag_names = mesh.tag_names;
  for (Index c = 0; c < mesh.num_cells(); ++c)
    soup.add_cell(kind, mesh.cells[c], mesh.cell_region[c]);
  for (std::size_t i = 0; i < mesh.boundary_faces.size(); ++i)
    soup.add_tagged_face(mesh.boundary_faces[i], mesh.boundary_tag[i]);
  return cells_to_poly(std::move(soup));
}

// Up to six faces of up to four corners: enough for tets and hexes, no heap allocation
// (classify_cell runs once per cell of every mesh that is written or measured).
using SmallLoops = std::array<std::array<Index, 4>, 6>;

// The n faces' vertex sets, each sorted on its first k entries, then sorted as a list.
SmallLoops canonical(SmallLoops loops, std::size_t n, std::size_t k) {
  for (std::size_t i = 0; i < n; ++i) std::sort(loops[i].begin(), loops[i].begin() + k);
  std::sort(loops.begin(), loops.begin() + n);
  return loops;
}

template <std::size_t NF, std::size_t F>
bool faces_match(const SmallLoops& sorted_actual, const std::array<Index, 8>& corners,
                 const std::array<std::array<int, F>, NF>& local_faces) {
  SmallLoops expected{};
  for (std::size_t i = 0; i < NF; ++i)
    for (std::size_t k = 0; k < F; ++k) expected[i][k] = corners[local_faces[i][k]];
  return canonical(expected, NF, F) == sorted_actual;
}

template <class Mesh>
Mesh poly_to_elements(const PolyMesh& mesh, CellShape shape, const char* name) {
  constexpr int C = Mesh::kCellCorners;
  constexpr int F = Mesh::kFaceCorners;
  Mesh out;
  out.points = mesh.points;
  out.cell_region = mesh.cell_region;
  out.tag_names = mesh.tag_names;
  const CellFaces cf = build_cell_faces(mesh);
  out.cells.resize(mesh.num_cells());
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const CellCorners cc = classify_cell(mesh, cf, c);
    if (cc.shape != shape)
      throw InputError("mesh: cell " + std::to_string(c) + " is not a " + name + " (" +
                       std::to_string(cf.of(c).size()) + " faces)");
    std::copy_n(cc.corners.begin(), C, out.cells[c].begin());
  }
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!mesh.is_boundary(f)) continue;
    std::array<Index, F> loop;
    std::copy_n(mesh.face(f).begin(), F, loop.begin());
    out.boundary_faces.push_back(loop);
    out.boundary_tag.push_back(mesh.face_tag[f]);
  }
  return out;
}

}  // namespace

PolyMesh to_poly_mesh(const TetMesh& mesh) { return element_to_poly(mesh, LinearCell::Tetrahedron); }
PolyMesh to_poly_mesh(const HexMesh& mesh) { return element_to_poly(mesh, LinearCell::Hexahedron); }

CellCorners classify_cell(const PolyMesh& mesh, const CellFaces& cell_faces, Index c) {
  CellCorners result;
  const auto faces = cell_faces.of(c);
  const std::size_t n = faces.size();
  if (n != 4 && n != 6) return result;
  const std::size_t k = n == 4 ? 3 : 4;
  SmallLoops loops{};  // outward from c
  for (std::size_t i = 0; i < n; ++i) {
    const auto loop = mesh.face(faces[i]);
    if (loop.size() != k) return result;
    std::copy(loop.begin(), loop.end(), loops[i].begin());
    if (mesh.owner[faces[i]] != c) std::reverse(loops[i].begin(), loops[i].begin() + k);
  }
  const SmallLoops sorted = canonical(loops, n, k);
  const auto& f0 = loops[0];
  const auto in_f0 = [&](Index v) { return std::find(f0.begin(), f0.begin() + k, v) != f0.begin() + k; };

  if (n == 4) {
    // Face 0 is seen counter-clockwise from outside; VTK wants it seen from the apex.
    Index apex = kNoIndex;
    for (std::size_t i = 0; i < 3; ++i)
      if (!in_f0(loops[1][i])) apex = loops[1][i];
    if (apex == kNoIndex) return result;
    result.corners = {f0[0], f0[2], f0[1], apex};
    if (faces_match(sorted, result.corners, kTetFaces)) result.shape = CellShape::Tetrahedron;
    return result;
  }
  // Hex: bottom = face 0 reversed (its normal then points into the cell, towards the top);
  // each bottom corner's top partner is the vertex joined to it by an edge off the bottom.
  const std::array<Index, 4> bottom{f0[0], f0[3], f0[2], f0[1]};
  std::array<Index, 8> corners{};
  for (int i = 0; i < 4; ++i) {
    corners[i] = bottom[i];
    Index partner = kNoIndex;
    for (std::size_t f = 1; f < 6; ++f)
      for (std::size_t e = 0; e < 4; ++e) {
        const Index a = loops[f][e], b = loops[f][(e + 1) % 4];
        const Index other = a == bottom[i] ? b : (b == bottom[i] ? a : kNoIndex);
        if (other == kNoIndex || in_f0(other)) continue;
        if (partner != kNoIndex && partner != other) return result;
        partner = other;
      }
    if (partner == kNoIndex) return result;
    corners[4 + i] = partner;
  }
  result.corners = corners;
  if (faces_match(sorted, corners, kHexFaces)) result.shape = CellShape::Hexahedron;
  return result;
}

TetMesh to_tet_mesh(const PolyMesh& mesh) {
  return poly_to_elements<TetMesh>(mesh, CellShape::Tetrahedron, "tetrahedron");
}
HexMesh to_hex_mesh(const PolyMesh& mesh) {
  return poly_to_elements<HexMesh>(mesh, CellShape::Hexahedron, "hexahedron");
}

}  // namespace volmesh
