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

// Two-sided Hausdorff distance, each side within `error_bound` of the true value (CGAL's
// bounded-error algorithm: exact point-triangle distances, subdividing triangles only where
// the bound is not yet met).
HausdorffDistance hausdorff_distance(const TriSurface& a, const TriSurface& b, double error_bound);

}  // namespace volmesh
