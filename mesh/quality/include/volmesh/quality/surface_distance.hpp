#pragma once
// How closely one triangulated surface approximates another: the geometric error of a
// mesh boundary against the true surface.
#include "volmesh/core/tri_surface.hpp"

namespace volmesh {

struct HausdorffDistance {
  double from_a = 0.0;  // max over points of a of the distance to b
  double from_b = 0.0;  // max over points of b of the distance to a
  double symmetric() const { return from_a > from_b ? from_a : from_b; }
};

// Two-sided Hausdorff distance, each side the distance of a point found on it, within
// `error_bound` below the true maximum: exact point-triangle distances at the corners,
// triangles subdivided only where the bound is not yet met, and pieces over coplanar
// triangles that cover them bounded at once, so that a mesh whose boundary lies on the
// surface's planar faces is measured in a fraction of a second.
HausdorffDistance hausdorff_distance(const TriSurface& a, const TriSurface& b, double error_bound);

}  // namespace volmesh
