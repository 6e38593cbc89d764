#pragma once
// The boundary of a PolyMesh as a triangulated surface.
#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/core/tri_surface.hpp"

namespace volmesh {

// Boundary faces (neighbour == kNoIndex), oriented outward. Triangles are kept; larger
// polygons are split into triangles around their vertex average, which is added as a point,
// so that non-convex faces of cut cells are triangulated without flips. Points are shared
// with the mesh (the same indices), extra centre points are appended.
TriSurface boundary_surface(const PolyMesh& mesh);

// The same with the faces between two regions added (oriented from owner to neighbour):
// every region's boundary, each interface once. Faces keep the mesh's order.
TriSurface region_boundary_surface(const PolyMesh& mesh);

}  // namespace volmesh
