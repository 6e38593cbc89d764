#include "feature_point.hpp"

#include <algorithm>
#include <limits>

#include "hex_mesh_geometry.hpp"
#include "volmesh/hexdc/qef.hpp"

namespace volmesh::hexdc_detail {
namespace {

// How far inside a boundary quad's centre feature_point probes the surface's normal, in shortest
// edges at the node: well below the half edge from the centre to the crease.
constexpr double kProbeDepth = 0.1;
// How far from a node surface_normals_at probes, in shortest edges at the node: near enough
// that a smooth surface's normal barely turns between the probes (a curvature radius of one
// edge turns it by about this many radians), far enough to reach both faces of a crease the
// node lies on.
constexpr double kNodeProbe = 0.05;
// How deep each of those probes lies, in its step toward the quad's centre: shallower than that
// step, so that a probe beside a crease or corner is nearest its own quad's face.
constexpr double kNodeProbeDepth = 0.25;

// The surface's tangent plane under boundary quad q: a probe a little inside the quad's centre
// and its closest point, whose segment is normal to the surface (the quad's own normal if the
// probe lies on the surface).
struct ProbedPlane {
  Vec3 foot, normal;
};

ProbedPlane probe_plane(const HexMesh& mesh, Index q, const SurfaceProjector& closest_point,
                        double reach) {
  Vec3 centre = Vec3::Zero();
  for (const Index c : mesh.boundary_faces[static_cast<std::size_t>(q)])
    centre += mesh.points[static_cast<std::size_t>(c)] / 4.0;
  const Vec3 outward = quad_vector_area(mesh, q).normalized();
  const Vec3 probe = centre - kProbeDepth * reach * outward;
  const Vec3 foot = closest_point(probe);
  const Vec3 found = (foot - probe).normalized();
  return {foot, found.isZero() ? outward : found};
}

}  // namespace

std::vector<Vec3> surface_normals_at(const HexMesh& mesh, const std::vector<Index>& quads,
                                     const SurfaceProjector& closest_point, std::size_t v,
                                     double reach) {
  const Vec3& x = mesh.points[v];
  const double step = kNodeProbe * reach;
  std::vector<Vec3> normals;
  normals.reserve(quads.size());
  for (const Index q : quads) {
    Vec3 centre = Vec3::Zero();
    for (const Index c : mesh.boundary_faces[static_cast<std::size_t>(q)])
      centre += mesh.points[static_cast<std::size_t>(c)] / 4.0;
    const Vec3 outward = quad_vector_area(mesh, q).normalized();
    const Vec3 probe = x + step * ((centre - x).normalized() - kNodeProbeDepth * outward);
    const Vec3 found = (closest_point(probe) - probe).normalized();
    normals.push_back(found.isZero() ? outward : found);
  }
  return normals;
}

// Where a crease or corner node belongs: the point nearest it on the surface's tangent planes
// at its quads' centres (solve_qef). Two planes of a crease meet in its line, three of a corner
// in it. Each plane is found from a probe a little inside the quad's centre: the segment to its
// closest point is normal to the surface, so a face's plane comes out exact however tilted the
// quad is; the probe stays near enough to its own face not to reach across the crease. The box,
// a shortest edge about the node, keeps a near-parallel pair from sending it far away.
Vec3 feature_point(const HexMesh& mesh, const std::vector<Index>& quads,
                   const SurfaceProjector& closest_point, std::size_t v, double reach) {
  const Vec3& x = mesh.points[v];
  std::vector<EdgeCrossing> planes;
  for (const Index q : quads) {
    const auto [foot, normal] = probe_plane(mesh, q, closest_point, reach);
    // Each plane by the node's own foot on it: the mass point of the feet then lies level with
    // the node along the crease, and solve_qef, which keeps the minimiser nearest the mass point
    // where the planes leave it free, does not slide the node along the crease.
    planes.push_back({x - normal.dot(x - foot) * normal, normal});
  }
  const Eigen::AlignedBox3d box(x - Vec3::Constant(reach), x + Vec3::Constant(reach));
  return solve_qef(planes, box).point;
}

double shortest_edge(const HexMesh& mesh, const std::vector<Index>& hexes, std::size_t v) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const Index h : hexes) {
    const auto& cell = mesh.cells[static_cast<std::size_t>(h)];
    for (const auto& [a, b] : kHexEdges)
      if (static_cast<std::size_t>(cell[a]) == v || static_cast<std::size_t>(cell[b]) == v)
        shortest = std::min(shortest, (mesh.points[static_cast<std::size_t>(cell[a])] -
                                       mesh.points[static_cast<std::size_t>(cell[b])]).norm());
  }
  return shortest;
}

}  // namespace volmesh::hexdc_detail
