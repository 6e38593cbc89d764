#pragma once
// Exact geometric predicates on surfaces. They are computed with CGAL's filtered predicates in
// surface_self_intersections.cpp, the one translation unit that includes CGAL.
#include <optional>

#include "volmesh/core/tri_surface.hpp"

namespace volmesh::surface_detail {

// The first triangle whose corners are exactly collinear (zero area), if any.
std::optional<Index> first_collinear_triangle(const TriSurface& surface);

}  // namespace volmesh::surface_detail
