#pragma once
// Self-intersections of a triangle soup, by CGAL's exact predicates (CGAL stays in the .cpp).
#include <cstddef>
#include <utility>
#include <vector>

#include "volmesh/core/tri_surface.hpp"

namespace volmesh {

// Pairs of triangles (i < j, sorted) that intersect in more than a shared vertex or edge,
// using CGAL's exact predicates; any triangle soup is accepted, degenerate triangles are
// skipped. At most max_pairs are returned; *truncated tells whether more exist.
std::vector<std::pair<Index, Index>> find_self_intersections(const TriSurface& surface,
                                                             std::size_t max_pairs,
                                                             bool* truncated = nullptr);

}  // namespace volmesh
