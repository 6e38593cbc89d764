#pragma once
// The front's rejection tests: CGAL's exact predicates on the doubles for every decision whose
// wrong sign would make the mesh invalid, but for one conservative tolerance (kNearlyFlat).
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
// the triangle, anywhere but at a shared corner or along a shared edge.
bool tet_meets_triangle(const std::array<Corner, 4>& tet, const std::array<Corner, 3>& tri);

}  // namespace volmesh::tet::front
