#pragma once
// Which closed surfaces hold which: the winding number of one surface's point about another.
#include <array>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::tet::front {

// The winding number of the closed triangles about p (p off them): the sum of their solid
// angles over 4π, outward triangles give 1 inside and 0 outside.
double winding_number(const std::vector<Vec3>& points,
                      const std::vector<std::array<Index, 3>>& triangles, const Vec3& p);

// For each of the closed, mutually disjoint surfaces (given by its triangles and a point on
// it), the surface that holds it most tightly, or kNoIndex.
std::vector<Index> parents(const std::vector<Vec3>& points,
                           const std::vector<std::vector<std::array<Index, 3>>>& surfaces);

}  // namespace volmesh::tet::front
