#pragma once
// The exact tests behind every change (CGAL's exact predicates on the doubles as they are
// written): a wrong sign here would invert a tet or move the boundary.
#include "volmesh/core/types.hpp"

namespace volmesh::improve {

// det(b - a, c - a, d - a) > 0, exactly.
bool positive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace volmesh::improve
