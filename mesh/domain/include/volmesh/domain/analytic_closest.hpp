#pragma once
// The closest surface point of one analytic primitive (analytic.hpp), exact up to rounding:
// closed forms, and Eberly's robust bisection for ellipsoids. Boundary data on the TRUE
// boundary (fem) and the surface distance to analytic domains (mesh/quality) both stand on it.
#include "volmesh/domain/analytic.hpp"

namespace volmesh {

// The closest point of prim's surface to p, and the unit outward normal there, both in world
// coordinates. A point with several closest points (a sphere's centre, a torus axis point)
// gets one of them.
struct SurfacePoint {
  Vec3 point;
  Vec3 normal;
};
SurfacePoint closest_surface_point(const Primitive& prim, const Vec3& p);

}  // namespace volmesh
