// The ten corner tets' signs by CGAL's exact orientation predicate on the corners as doubles:
// a wrong sign would let a folded hex through, and the doubles are what the mesh is written with.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>

#include "volmesh/hexdc/hex_quality.hpp"

namespace volmesh {

bool hex_corner_tets_positive(const std::array<Vec3, 8>& corners) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::array<Point, 8> p;
  std::transform(corners.begin(), corners.end(), p.begin(),
                 [](const Vec3& x) { return Point(x.x(), x.y(), x.z()); });
  return std::all_of(kHexCornerTets.begin(), kHexCornerTets.end(), [&](const auto& tet) {
    const auto& [a, b, c, d] = tet;
    return CGAL::orientation(p[a], p[b], p[c], p[d]) == CGAL::POSITIVE;
  });
}

}  // namespace volmesh
