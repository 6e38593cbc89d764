#pragma once
// The sub-tessellation behind the polyhedral space (fem.hpp, Space::polyhedral), public so
// that other discretisations integrate over general cells the same way.
//
// A cell is cut into tetrahedra (apex, p, q, m) around an apex inside it: for each face of
// four or more vertices, one per edge (p, q) of the outward face loop, with m the face's
// vertex average — the same fan core/geometry.hpp uses for face areas and cell volumes, so
// the sub-tetrahedra of a cell add up to its volume and the two cells of a face fan it alike;
// a triangular face gives the single tetrahedron (apex, v0, v1, v2).
#include <span>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh::fem {

// Vertex average of the distinct vertices of cell c (faces = its faces).
Vec3 cell_vertex_average(const PolyMesh& mesh, std::span<const Index> faces);

// Vertex average of face f's loop.
inline Vec3 face_vertex_average(const PolyMesh& mesh, Index f) {
  Vec3 m = Vec3::Zero();
  const auto loop = mesh.face(f);
  for (Index v : loop) m += mesh.points[v];
  return m / static_cast<double>(loop.size());
}

// One sub-tetrahedron of cell c on face `face`, positively oriented for a cell star-shaped
// about the apex. For a fanned face, `p` and `q` are positions k and k+1 of the face loop
// taken in the cell's outward orientation and the fourth corner is the face's vertex
// average; for a triangle `p`, `q`, `r` are its three loop positions (outward).
struct SubTetrahedron {
  Index face;
  bool fanned;      // face of four or more vertices
  int p, q, r;      // loop positions; r = -1 when fanned
  Vec3 corners[4];  // apex, loop[p], loop[q], face average (fanned) or loop[r]
};

// Calls fn(const SubTetrahedron&) for every sub-tetrahedron of cell c in face order.
template <class Fn>
void for_each_sub_tetrahedron(const PolyMesh& mesh, std::span<const Index> faces, Index c,
                              const Vec3& apex, Fn&& fn) {
  SubTetrahedron t;
  t.corners[0] = apex;
  for (Index f : faces) {
    const auto loop = mesh.face(f);
    const int n = static_cast<int>(loop.size());
    const bool outward = mesh.owner[f] == c;
    // Position of the k-th vertex in the cell's outward orientation of the loop.
    const auto at = [&](int k) { return outward ? k % n : (n - k % n) % n; };
    t.face = f;
    if (n == 3) {
      t.fanned = false;
      t.p = at(0), t.q = at(1), t.r = at(2);
      t.corners[1] = mesh.points[loop[t.p]];
      t.corners[2] = mesh.points[loop[t.q]];
      t.corners[3] = mesh.points[loop[t.r]];
      fn(static_cast<const SubTetrahedron&>(t));
      continue;
    }
    t.fanned = true;
    t.r = -1;
    t.corners[3] = face_vertex_average(mesh, f);
    for (int k = 0; k < n; ++k) {
      t.p = at(k), t.q = at(k + 1);
      t.corners[1] = mesh.points[loop[t.p]];
      t.corners[2] = mesh.points[loop[t.q]];
      fn(static_cast<const SubTetrahedron&>(t));
    }
  }
}

}  // namespace volmesh::fem
