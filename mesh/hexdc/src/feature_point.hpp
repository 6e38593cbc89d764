#pragma once
// Where a crease or corner node of a hex mesh's boundary belongs on the surface (project.hpp,
// untangle.hpp).
#include <cstddef>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/hexdc/surface_projector.hpp"

namespace volmesh::hexdc_detail {

// The point nearest node v on the surface's tangent planes at its boundary quads' centres: two
// planes of a crease meet in its line, three of a corner in it. `reach` bounds the move.
Vec3 feature_point(const HexMesh& mesh, const std::vector<Index>& quads,
                   const SurfaceProjector& closest_point, std::size_t v, double reach);

// The surface's unit normals beside node v, one per boundary quad of `quads`: each from a probe a
// small fraction of `reach` from the node toward the quad's centre and inward, and the segment
// to its closest point. They spread on a crease or corner of the surface the node lies on and
// agree on a smooth part however coarse the quads are, unlike the normals under the quads'
// centres or the quads' own.
std::vector<Vec3> surface_normals_at(const HexMesh& mesh, const std::vector<Index>& quads,
                                     const SurfaceProjector& closest_point, std::size_t v,
                                     double reach);

// The shortest hex edge at node v among `hexes`.
double shortest_edge(const HexMesh& mesh, const std::vector<Index>& hexes, std::size_t v);

}  // namespace volmesh::hexdc_detail
