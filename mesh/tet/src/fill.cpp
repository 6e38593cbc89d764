// Stage 5: each prism is convex (a triangular column cut by two planes), so the tets joining
// an interior point to its boundary triangles fill it; the mean of its six corners is
// interior, since every corner weighs in and the prism has volume. The tets are positive by
// construction; the rounding re-tests each one (rounding.hpp), and the tests check them
// exactly.

#include <algorithm>
#include <tuple>
#include <vector>

#include "projection_data.hpp"

namespace volmesh::tet::detail {

void fill(State& state, ProjectionMesh& mesh) {
  for (std::size_t p = 0; p < state.prisms.size(); ++p) {
    const Prism& prism = state.prisms[p];
    const auto& caps = state.prism_boundary[p];
    // The two caps hold the six corners.
    RationalPoint o{0, 0, 0};
    for (int c = 0; c < 2; ++c)
      for (const Index q : caps[c].points) {
        o.x += state.points[q].x;
        o.y += state.points[q].y;
        o.z += state.points[q].z;
      }
    o.x /= 6;
    o.y /= 6;
    o.z /= 6;
    const Index centre = static_cast<Index>(state.points.size());
    state.points.push_back(std::move(o));
    // The stitching meets a prism's triangles in an order that follows the plane
    // triangulation's history, not its result: they are numbered canonically (each from its
    // least corner, then in order), so that the same input gives the same tets.
    std::vector<BoundaryTriangle> ordered = caps;  // the caps stay first for the stats
    for (BoundaryTriangle& t : ordered)
      std::rotate(t.points.begin(), std::min_element(t.points.begin(), t.points.end()),
                  t.points.end());
    std::sort(ordered.begin(), ordered.end(),
              [](const BoundaryTriangle& x, const BoundaryTriangle& y) {
                return std::tie(x.points, x.on) < std::tie(y.points, y.on);
              });
    for (const BoundaryTriangle& t : ordered) {
      const auto& [a, b, c] = t.points;
      mesh.tets.push_back({a, c, b, centre});
      mesh.tet_region.push_back(prism.region);
      if (t.on != kNoIndex) {
        mesh.boundary_faces.push_back(t.points);
        mesh.boundary_surface.push_back(state.input.surface[t.on]);
        mesh.boundary_carrier.push_back(state.input.triangles[t.on]);
      }
    }
  }
}

}  // namespace volmesh::tet::detail
