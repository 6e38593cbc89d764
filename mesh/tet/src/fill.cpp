// Stage 5: each prism is convex (a triangular column cut by two planes), so the tets joining
// an interior point to its boundary triangles fill it; the mean of its six corners is
// interior, since every corner weighs in and the prism has volume.
#include <stdexcept>

#include "projection_data.hpp"

namespace volmesh::tet::detail {

void fill(State& state, ProjectionMesh& mesh) {
  for (std::size_t p = 0; p < state.prisms.size(); ++p) {
    const Prism& prism = state.prisms[p];
    const auto& caps = state.prism_boundary[p];
    // The two caps hold the six corners.
    FT x = 0, y = 0, z = 0;
    for (int c = 0; c < 2; ++c)
      for (const Index q : caps[c].points) {
        x += state.points[q].x();
        y += state.points[q].y();
        z += state.points[q].z();
      }
    const Index centre = static_cast<Index>(state.points.size());
    state.points.emplace_back(x / 6, y / 6, z / 6);
    const Point3& o = state.points.back();
    for (const BoundaryTriangle& t : caps) {
      const auto& [a, b, c] = t.points;
      if (CGAL::orientation(state.points[a], state.points[c], state.points[b], o) !=
          CGAL::POSITIVE)
        throw std::logic_error("tet-projection: a tet of prism " + std::to_string(p) +
                               " is not positive");
      mesh.tets.push_back({a, c, b, centre});
      mesh.tet_region.push_back(prism.region);
      if (t.on != kNoIndex) {
        mesh.boundary_faces.push_back(t.points);
        mesh.boundary_surface.push_back(state.input.surface[t.on]);
      }
    }
  }
}

}  // namespace volmesh::tet::detail
