#pragma once
// The improvement pass's quality measure: the smallest sine of a tet's six dihedral angles,
// signed by its volume. 0.943 for the regular tet, near 0 for a tet with a dihedral angle near
// 0° or 180° (slivers, caps, wedges), negative for an inverted tet. It tracks the min dihedral
// angle (sin 10° = 0.174) and, unlike it, the max dihedral angle too.
#include <algorithm>
#include <cmath>
#include <limits>

#include "volmesh/core/types.hpp"

namespace volmesh::tet::front {

// Along edge ij, with k, l the other corners: sin θ_ij = 6V · |ij| / (|n_k| |n_l|), n_k the
// area vector (twice the area) of the face opposite k.
inline double min_sine(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const Vec3 e01 = p1 - p0, e02 = p2 - p0, e03 = p3 - p0, e12 = p2 - p1, e13 = p3 - p1,
             e23 = p3 - p2;
  const double six_volume = e01.dot(e02.cross(e03));
  // Twice the areas of the faces opposite each corner.
  const double n0 = e12.cross(e13).norm(), n1 = e02.cross(e03).norm(), n2 = e01.cross(e03).norm(),
               n3 = e01.cross(e02).norm();
  const double a = e01.norm() / (n2 * n3), b = e02.norm() / (n1 * n3), c = e03.norm() / (n1 * n2),
               d = e12.norm() / (n0 * n3), e = e13.norm() / (n0 * n2), f = e23.norm() / (n0 * n1);
  const double shortest = std::min({a, b, c, d, e, f});
  const double largest = std::max({a, b, c, d, e, f});
  if (!(six_volume > 0.0)) {
    // Flat or inverted: ordered by how far inverted (a zero-area face counts as flat).
    return std::isfinite(largest) ? six_volume * largest : -std::numeric_limits<double>::max();
  }
  return six_volume * shortest;
}

}  // namespace volmesh::tet::front
