#include "volmesh/quality/surface_distance.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Surface_mesh.h>

namespace volmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

// A triangle soup as a Surface_mesh: the distance algorithm only needs faces, not a
// manifold connectivity, so every triangle gets its own three vertices.
Mesh to_cgal(const TriSurface& s) {
  Mesh m;
  m.reserve(3 * s.triangles.size(), 3 * s.triangles.size(), s.triangles.size());
  for (const auto& t : s.triangles) {
    std::array<Mesh::Vertex_index, 3> v;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = s.points[t[k]];
      v[k] = m.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
    }
    m.add_face(v[0], v[1], v[2]);
  }
  return m;
}

}  // namespace

HausdorffDistance hausdorff_distance(const TriSurface& a, const TriSurface& b, double error_bound) {
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Mesh ma = to_cgal(a), mb = to_cgal(b);
  return {PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(ma, mb, error_bound),
          PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(mb, ma, error_bound)};
}

}  // namespace volmesh
