#pragma once
// Exact predicates on the triangles of a surface. They are computed with CGAL's filtered
// predicates in self_intersections.cpp, the one translation unit that includes CGAL.
#include <optional>

#include "volmesh/core/tri_surface.hpp"

namespace volmesh::geometry_detail {

// The first triangle whose corners are exactly collinear (zero area), if any.
std::optional<Index> first_collinear_triangle(const TriSurface& surface);

}  // namespace volmesh::geometry_detail
