#pragma once
// Where a boundary point of a tet mesh may slide while the boundary stays the same surface:
// inside a triangle of that surface (in its plane) or along one of its edges. A point at a
// surface vertex, or off the surface, stays put.
#include <array>
#include <cstdint>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/tri_surface.hpp"

namespace volmesh::improve {

enum class SlideKind : std::uint8_t { None, Plane, Line };

struct Slide {
  SlideKind kind = SlideKind::None;
  // Plane: the triangle the point stays in; Line: the segment (corners 0 and 1).
  std::array<Vec3, 3> corners{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
};

// Per point of `mesh`: the triangle or edge of `surface` that a point of the mesh boundary
// lies in, exactly (its relative interior); None for the other points, interface points
// included.
std::vector<Slide> slides_on_surface(const TetMesh& mesh, const TriSurface& surface);

// Whether p lies in the closed triangle or segment of `slide`, exactly.
bool stays_within(const Slide& slide, const Vec3& p);

}  // namespace volmesh::improve
