#pragma once
// The front's rejection tests: CGAL's exact predicates on the doubles for every decision whose
// wrong sign would make the mesh invalid.
#include <array>

#include "volmesh/core/types.hpp"

namespace volmesh::tet::front {

// det(b - a, c - a, d - a) > 0, exactly.
bool positive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// A corner with its point and its index in the mesh (shared corners are told by index).
struct Corner {
  Vec3 p;
  Index id;
};

// Whether the positive tet and the front triangle meet beyond the corners they share: a
// triangle corner in the closed tet, a triangle edge meeting a tet face or a tet edge meeting
// the triangle, anywhere but at a shared corner or along a shared edge. Exact; a plane
// through the shared corners (or any plane when they share none) that separates them settles
// most pairs before the edge-by-edge tests.
bool tet_meets_triangle(const std::array<Corner, 4>& tet, const std::array<Corner, 3>& tri);

// A shape rule, not a validity test: whether an edge of the tet at a corner it shares with the
// front triangle lies over the triangle within a sine of 1e-6 of its plane, or an edge of the
// triangle over a face of the tet likewise. The gap left between them would be flatter than
// any tet could fill (four corners on one plane up to rounding), and the stalled cavity of
// such gaps flatter than the fallback's projection can round to doubles.
bool leaves_flat_gap(const std::array<Corner, 4>& tet, const std::array<Corner, 3>& tri);

}  // namespace volmesh::tet::front
