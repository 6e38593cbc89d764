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

// The surface's unit normals under the boundary quads `quads` (probed as feature_point's planes).
std::vector<Vec3> surface_normals(const HexMesh& mesh, const std::vector<Index>& quads,
                                  const SurfaceProjector& closest_point, double reach);

// Whether node v is on a crease or corner of the surface itself: the surface's normals under its
// boundary quads (probed as feature_point's planes) leave their mean by more than the feature
// angle. Unlike the mesh's quad normals, these do not make a node with a folded quad a feature.
bool on_surface_feature(const HexMesh& mesh, const std::vector<Index>& quads,
                        const SurfaceProjector& closest_point, double reach, double cos_feature);

// The shortest hex edge at node v among `hexes`.
double shortest_edge(const HexMesh& mesh, const std::vector<Index>& hexes, std::size_t v);

}  // namespace volmesh::hexdc_detail
