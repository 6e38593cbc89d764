#include "volmesh/quality/tet_metrics.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/geometry.hpp"

namespace volmesh {

TetMetrics tet_metrics(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const std::array<const Vec3*, 4> p{&a, &b, &c, &d};
  TetMetrics m;
  double min_angle = std::numbers::pi, max_angle = 0.0;
  double shortest2 = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < kTetEdges.size(); ++e) {
    // Edge (i, j) and the two other corners (k, l).
    const auto& [i, j] = kTetEdges[e];
    const auto& [k, l] = kTetEdges[kTetOppositeEdges[e]];
    const Vec3& o = *p[i];
    const Vec3 edge = *p[j] - o;
    // Crossing with the edge projects k and l onto the plane normal to the edge (and turns
    // both by 90°): the angle between the results is the dihedral angle along the edge.
    const Vec3 u = edge.cross(*p[k] - o);
    const Vec3 v = edge.cross(*p[l] - o);
    const double angle = std::atan2(u.cross(v).norm(), u.dot(v));
    min_angle = std::min(min_angle, angle);
    max_angle = std::max(max_angle, angle);
    shortest2 = std::min(shortest2, edge.squaredNorm());
  }
  constexpr double deg = 180.0 / std::numbers::pi;
  m.min_dihedral_deg = min_angle * deg;
  m.max_dihedral_deg = max_angle * deg;
  m.volume = tet_volume(a, b, c, d);

  if (m.volume == 0.0) {
    m.radius_edge_ratio = m.aspect_ratio = std::numeric_limits<double>::infinity();
    return m;
  }
  // Circumcentre relative to a: (|B|²(C×D) + |C|²(D×B) + |D|²(B×C)) / (2 B·(C×D)).
  const Vec3 B = b - a, C = c - a, D = d - a;
  const Vec3 offset =
      B.squaredNorm() * C.cross(D) + C.squaredNorm() * D.cross(B) + D.squaredNorm() * B.cross(C);
  const double circumradius = offset.norm() / std::abs(12.0 * m.volume);
  const double area = 0.5 * (B.cross(C).norm() + B.cross(D).norm() + C.cross(D).norm() +
                             (c - b).cross(d - b).norm());
  const double inradius = 3.0 * std::abs(m.volume) / area;
  m.radius_edge_ratio = circumradius / std::sqrt(shortest2);
  m.aspect_ratio = circumradius / (3.0 * inradius);
  return m;
}

}  // namespace volmesh
