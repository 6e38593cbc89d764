#include "volmesh/hexdc/hex_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/quality/hex_metrics.hpp"

namespace volmesh {
namespace {

constexpr double kRightAngleDeg = 90.0;
constexpr double kFullTurnDeg = 360.0;
constexpr double kDegPerRad = 180.0 / std::numbers::pi;
// The two inner tets of kHexCornerTets; the other eight are the corner tets of the scaled
// Jacobian's corners, with the same corner and edge order.
constexpr std::array<std::size_t, 2> kInnerTets{4, 9};
// The inner tets' edges at their first corner are face diagonals, √2 each, in the unit cube,
// where 6 V = 2: the normalised volume 2 / (2√2) times √2 is 1.
constexpr double kInnerTetScale = std::numbers::sqrt2;

}  // namespace

std::array<double, 10> hex_corner_tet_volumes(const std::array<Vec3, 8>& p) {
  std::array<double, 10> volumes{};
  for (std::size_t t = 0; t < kHexCornerTets.size(); ++t) {
    const auto& [a, b, c, d] = kHexCornerTets[t];
    volumes[t] = tet_volume(p[a], p[b], p[c], p[d]);
  }
  return volumes;
}

std::array<double, 4> quad_interior_angles_deg(const std::array<Vec3, 4>& q) {
  // Unit normal of the vector area; zero for a quad of no area, whose angles are then 0 or 180.
  const Vec3 normal = (q[2] - q[0]).cross(q[3] - q[1]).normalized();
  std::array<double, 4> angles{};
  for (int k = 0; k < 4; ++k) {
    const Vec3 next = q[(k + 1) % 4] - q[k], previous = q[(k + 3) % 4] - q[k];
    // atan2 keeps the digits near 0° and 180° that acos of the normalised dot loses.
    double angle = std::atan2(next.cross(previous).dot(normal), next.dot(previous)) * kDegPerRad;
    if (angle < 0.0) angle += kFullTurnDeg;
    angles[static_cast<std::size_t>(k)] = angle;
  }
  return angles;
}

HexGrade hex_grade(const std::array<Vec3, 8>& p) {
  return {hex_scaled_jacobian(p), hex_corner_tets_positive(p)};
}

double hex_shape_quality(const std::array<Vec3, 8>& p) {
  double quality = hex_scaled_jacobian(p);
  for (const std::size_t t : kInnerTets) {
    const auto& [a, b, c, d] = kHexCornerTets[t];
    const Vec3 e1 = p[b] - p[a], e2 = p[c] - p[a], e3 = p[d] - p[a];
    const double lengths = e1.norm() * e2.norm() * e3.norm();
    const double normalised = lengths > 0.0 ? kInnerTetScale * e1.dot(e2.cross(e3)) / lengths : 0.0;
    quality = std::min(quality, normalised);
  }
  return quality;
}

HexQuality hex_quality(const std::array<Vec3, 8>& p) {
  HexQuality quality;
  quality.corner_tets_positive = hex_corner_tets_positive(p);
  quality.scaled_jacobian = hex_scaled_jacobian(p);
  for (const auto& face : kHexFaces) {
    const std::array<Vec3, 4> quad{p[face[0]], p[face[1]], p[face[2]], p[face[3]]};
    for (const double angle : quad_interior_angles_deg(quad)) {
      quality.max_quad_angle_deg = std::max(quality.max_quad_angle_deg, angle);
      quality.max_quad_distortion_deg =
          std::max(quality.max_quad_distortion_deg, std::abs(angle - kRightAngleDeg));
    }
  }
  quality.min_edge = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : kHexEdges) {
    const double length = (p[b] - p[a]).norm();
    quality.min_edge = std::min(quality.min_edge, length);
    quality.max_edge = std::max(quality.max_edge, length);
  }
  return quality;
}

}  // namespace volmesh
