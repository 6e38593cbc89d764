#pragma once
// Closest points on a surface: a bounding-volume hierarchy over the triangles built for
// point queries (CGAL's AABB tree answers them six times slower, too slow for a dense
// signed-distance grid), and the signed distance of Bærentzen & Aanæs: the distance to the
// closest point, negative where p lies on the outer side of that feature's pseudo-normal.
#include <array>
#include <cstdint>
#include <vector>

#include "surface_geometry.hpp"

namespace volmesh::surface {

struct ClosestPoint {
  Vec3 point = Vec3::Zero();
  double squared_distance = 0.0;
  Index triangle = kNoIndex;
  Feature feature = Feature::face;
};

// The closest point of triangle (a, b, c) to p and the feature it lies on (Ericson,
// Real-Time Collision Detection, 5.1.5).
ClosestPoint closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// Four children per node, each a node or a single triangle, bounded twice: by its box and
// by a cylinder around an axis (a disk for a triangle: the smallest enclosing one; a thin
// cylinder for a nearly flat patch; a ball where the axis is 0). The distance to either is
// a lower bound of the child's; the cylinder's is much the tighter one for tilted
// triangles. Side by side in float, relative to the surface's centre and enlarged for
// rounding, so that the four children are measured in one vector operation.
using Float4 = float __attribute__((vector_size(16)));  // GCC/Clang vector extension
struct ClosestNode {
  Float4 lo[3], hi[3];  // an empty child has lo = +inf, hi = -inf
  Float4 centre[3], axis[3];
  Float4 half_height, radius;
  std::array<std::int32_t, 4> child;  // >= 0: a node; < 0: ~(leaf slot of a triangle)
};
// At most this many binary levels deep (the surface-area heuristic stops 32 levels short,
// median splits finish in 31 for 2^31 triangles).
inline constexpr int kMaxClosestDepth = 80;

struct ClosestHierarchy {
  std::vector<ClosestNode> nodes;  // nodes[0] is the root
  std::vector<Index> triangles;    // leaf slot -> triangle
};
// Binary splits by the surface-area heuristic, collapsed to four children per node
// (surface_closest_build.cpp).
ClosestHierarchy build_closest_hierarchy(const SurfaceGeometry& geometry, const Vec3& centre);

class ClosestTree {
 public:
  explicit ClosestTree(const SurfaceGeometry& geometry);

  // The closest point of the whole surface, exact up to the rounding of the point-triangle
  // distance; p finite, |p| < 1e30. `hint`, a triangle near p (e.g. the answer for a
  // neighbouring point), only speeds the search up: the result does not depend on it except
  // between triangles at equal distance.
  ClosestPoint closest(const Vec3& p, Index hint = kNoIndex) const;

 private:
  void visit(const Vec3& p, Index slot, ClosestPoint& best) const;

  Vec3 centre_;
  double scale_;  // largest coordinate of a corner relative to centre_
  ClosestHierarchy tree_;
  std::vector<std::array<Vec3, 3>> corners_;  // per leaf slot
  std::vector<Index> slot_;                   // triangle -> leaf slot
};

// Positive inside, negative outside, 0 on the surface (the hex paper's convention).
double signed_distance(const SurfaceGeometry& geometry, const Vec3& p, const ClosestPoint& c);

}  // namespace volmesh::surface
