#include "volmesh/core/boundary.hpp"

namespace volmesh {
namespace {

// The faces for which keep(f) holds, in order, as triangles (see boundary_surface).
template <class Keep>
TriSurface triangulate_faces(const PolyMesh& mesh, Keep keep) {
  TriSurface s;
  s.points = mesh.points;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!keep(f)) continue;
    const auto loop = mesh.face(f);
    const std::size_t n = loop.size();
    if (n == 3) {
      s.triangles.push_back({loop[0], loop[1], loop[2]});
      continue;
    }
    Vec3 mid = Vec3::Zero();
    for (Index v : loop) mid += mesh.points[v];
    s.points.push_back(mid / static_cast<double>(n));
    const Index c = s.num_points() - 1;
    for (std::size_t i = 0; i < n; ++i) s.triangles.push_back({loop[i], loop[(i + 1) % n], c});
  }
  return s;
}

}  // namespace

TriSurface boundary_surface(const PolyMesh& mesh) {
  return triangulate_faces(mesh, [&](Index f) { return mesh.is_boundary(f); });
}

TriSurface region_boundary_surface(const PolyMesh& mesh) {
  return triangulate_faces(mesh, [&](Index f) {
    return mesh.is_boundary(f) ||
           mesh.cell_region[mesh.owner[f]] != mesh.cell_region[mesh.neighbour[f]];
  });
}

}  // namespace volmesh
