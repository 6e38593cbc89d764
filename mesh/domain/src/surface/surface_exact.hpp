#pragma once
// Exact segment queries on the triangles of a SurfaceGeometry: a CGAL AABB tree finds the
// triangles whose box the segment meets, CGAL's exact orientation predicates decide where
// the segment meets each (nowhere, the interior, a side, a corner, or in its plane). The
// winding number of a point counts the signed crossings of a ray, exactly, shooting again
// in another direction when the ray meets a side or a corner. CGAL stays in the .cpp.
#include <cstdint>
#include <memory>
#include <vector>

#include "surface_geometry.hpp"

namespace volmesh::surface {

// How the closed segment [a, b] meets a triangle.
struct SegmentHit {
  Index triangle;
  // Side of a and of b with respect to the triangle's plane: +1 on the outer side (where
  // its normal points), -1 on the inner side, 0 in the plane.
  int side_a, side_b;
  bool coplanar;    // both in the plane, and the segment meets the triangle
  Feature feature;  // where the segment's line meets the triangle (face when coplanar)
};

// Containment of a point by one surface: its winding number, and whether it lies on it.
struct Containment {
  int winding = 0;
  bool on = false;
  bool inside() const { return on || winding > 0; }
};

// How the closed segment [a, b] meets triangle t of the geometry, if it does (exact; the
// test ExactTree::hits applies to its candidates).
bool segment_hit(const SurfaceGeometry& geometry, Index t, const Vec3& a, const Vec3& b, SegmentHit& hit);

class ExactTree {
 public:
  explicit ExactTree(const SurfaceGeometry& geometry);
  ~ExactTree();
  ExactTree(const ExactTree&) = delete;
  ExactTree& operator=(const ExactTree&) = delete;

  // Every triangle the closed segment meets, by increasing triangle index.
  std::vector<SegmentHit> hits(const Vec3& a, const Vec3& b) const;
  // Per surface of the geometry. Exact for every finite p.
  std::vector<Containment> containment(const Vec3& p) const;

 private:
  struct Impl;
  std::unique_ptr<const Impl> impl_;
};

// The parameter t of the point where the segment crosses the hit triangle's plane
// (0 or 1 when an end point lies in it), in [0, 1].
double crossing_parameter(const SurfaceGeometry& geometry, const Vec3& a, const Vec3& b,
                          const SegmentHit& hit);

// A face interior, edge or vertex the segment meets strictly between its ends.
struct SegmentEvent {
  double t;
  std::uint64_t key;  // the feature met: unique over all surfaces of the geometry
  const SegmentHit* hit;
};

// The hits sorted out: those with an end point in the triangle's plane, and one event per
// feature met between the ends (from its lowest triangle), by increasing t.
struct SegmentEvents {
  std::vector<const SegmentHit*> at_a, at_b;
  std::vector<SegmentEvent> events;
};
SegmentEvents segment_events(const SurfaceGeometry& geometry, const Vec3& a, const Vec3& b,
                             const std::vector<SegmentHit>& hits);

}  // namespace volmesh::surface
