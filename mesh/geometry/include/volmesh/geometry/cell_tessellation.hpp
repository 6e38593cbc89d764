#pragma once
// Polyhedral cells as tetrahedra: the sub-tessellation behind the polyhedral FEM's
// integration (fem/polyhedral.hpp) and the conforming tet decomposition on export
// (tet_decomposition.hpp).
//
// Faces: a face of four or more vertices is fanned into triangles (p, q, m) about its vertex
// average m — the fan core/geometry.hpp uses for face areas and cell volumes — when that fan
// is proper (every triangle turns the same way as the face). A non-convex face (a cube face
// cut along a bent contour) can fold its fan; it is triangulated by ear clipping instead,
// without a face node, unless those triangles cross in space (a warped face). The split is a
// property of the face, so both of its cells use it.
// Cells: a tetrahedron (apex, triangle) on every face triangle, about an apex that sees them
// all (star_centre).
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// Vertex average of face f's loop.
inline Vec3 face_vertex_average(const PolyMesh& mesh, Index f) {
  Vec3 m = Vec3::Zero();
  const auto loop = mesh.face(f);
  for (Index v : loop) m += mesh.points[v];
  return m / static_cast<double>(loop.size());
}

// The faces that are not fanned, with their triangles as loop positions in the face's own
// orientation. A face is fanned even where the fan folds in projection when the ear
// clipping crosses itself in space; `folded` marks a face whose fan crosses itself too (a
// polygon folded over itself: no cell on it is valid).
struct FaceSplits {
  std::vector<Index> offsets;  // per face, into triangles; empty for a fanned face or a triangle
  std::vector<std::array<int, 3>> triangles;
  std::vector<char> folded;  // per face
  bool fanned(const PolyMesh& mesh, Index f) const {
    return offsets[f] == offsets[f + 1] && mesh.face(f).size() > 3;
  }
};
FaceSplits split_faces(const PolyMesh& mesh);

// One sub-tetrahedron of cell c on face `face`. `p`, `q` are loop positions taken in the
// cell's outward orientation; the fourth corner is the face's vertex average when `fanned`,
// else loop position `r` (r = -1 when fanned).
struct SubTetrahedron {
  Index face;
  bool fanned;
  int p, q, r;
  Vec3 corners[4];  // apex, loop[p], loop[q], face average or loop[r]
};

// Calls fn(const SubTetrahedron&) for every sub-tetrahedron of cell c, face by face in the
// order of `faces`; positively oriented when the apex sees every face triangle from inside.
template <class Fn>
void for_each_sub_tetrahedron(const PolyMesh& mesh, const FaceSplits& splits,
                              std::span<const Index> faces, Index c, const Vec3& apex, Fn&& fn) {
  SubTetrahedron t;
  t.corners[0] = apex;
  for (Index f : faces) {
    const auto loop = mesh.face(f);
    const int n = static_cast<int>(loop.size());
    const bool outward = mesh.owner[f] == c;
    t.face = f;
    const auto corner = [&](int i, int position) { t.corners[i] = mesh.points[loop[position]]; };
    if (!splits.fanned(mesh, f)) {
      t.fanned = false;
      const std::array<int, 3> single{0, 1, 2};
      const std::span<const std::array<int, 3>> triangles =
          n == 3 ? std::span<const std::array<int, 3>>(&single, 1)
                 : std::span<const std::array<int, 3>>(splits.triangles)
                       .subspan(splits.offsets[f], splits.offsets[f + 1] - splits.offsets[f]);
      for (const auto& tri : triangles) {
        t.p = tri[0];
        t.q = outward ? tri[1] : tri[2];
        t.r = outward ? tri[2] : tri[1];
        corner(1, t.p);
        corner(2, t.q);
        corner(3, t.r);
        fn(static_cast<const SubTetrahedron&>(t));
      }
      continue;
    }
    // Position of the k-th vertex in the cell's outward orientation of the loop.
    const auto at = [&](int k) { return outward ? k % n : (n - k % n) % n; };
    t.fanned = true;
    t.r = -1;
    t.corners[3] = face_vertex_average(mesh, f);
    for (int k = 0; k < n; ++k) {
      t.p = at(k), t.q = at(k + 1);
      corner(1, t.p);
      corner(2, t.q);
      fn(static_cast<const SubTetrahedron&>(t));
    }
  }
}

// A point from which every face triangle of cell c is seen from inside, each sub-tetrahedron
// with a volume above 1e-12 of its longest edge cubed: the vertex average when it does, else
// the centroid, else a point of the cell's kernel found by the relaxation method (Agmon,
// Motzkin–Schoenberg) on the triangles' planes. Empty when none is found: the cell is
// inverted, degenerate or not star-shaped.
std::optional<Vec3> star_centre(const PolyMesh& mesh, const FaceSplits& splits,
                                std::span<const Index> faces, Index c);

}  // namespace volmesh
