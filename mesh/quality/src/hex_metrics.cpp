#include "volmesh/quality/hex_metrics.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh {

HexJacobians hex_jacobians(const std::array<Vec3, 8>& p) {
  // Corner k's frame: the edges to its three neighbours, positive in a valid hex.
  std::array<std::array<Vec3, 3>, 9> frames;
  for (int k = 0; k < 8; ++k) {
    const auto& [corner, a, b, c] = kHexCornerFrames[k];
    frames[k] = {p[a] - p[corner], p[b] - p[corner], p[c] - p[corner]};
  }
  // Derivatives of the trilinear map at the centre (times 4).
  frames[8] = {(p[1] + p[2] + p[5] + p[6]) - (p[0] + p[3] + p[4] + p[7]),
               (p[2] + p[3] + p[6] + p[7]) - (p[0] + p[1] + p[4] + p[5]),
               (p[4] + p[5] + p[6] + p[7]) - (p[0] + p[1] + p[2] + p[3])};

  HexJacobians result;
  std::array<double, 9> determinants;
  std::array<double, 9> lengths2;  // the product of the squared lengths of each frame's edges
  double longest2 = 0.0, shortest2 = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto& [e1, e2, e3] = frames[k];
    const double l1 = e1.squaredNorm(), l2 = e2.squaredNorm(), l3 = e3.squaredNorm();
    longest2 = std::max({longest2, l1, l2, l3});
    shortest2 = std::min({shortest2, l1, l2, l3});
    determinants[k] = e1.dot(e2.cross(e3));
    lengths2[k] = l1 * l2 * l3;
  }
  std::copy_n(determinants.begin(), 8, result.corner_determinants.begin());
  constexpr double kCollapsed2 = 1e-24;  // (1e-12)²: relative length of a collapsed edge
  if (shortest2 <= kCollapsed2 * longest2) return result;  // scaled_jacobian 0
  double scaled = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < frames.size(); ++k)
    scaled = std::min(scaled, determinants[k] / std::sqrt(lengths2[k]));
  result.scaled_jacobian = scaled;
  return result;
}

double hex_scaled_jacobian(const std::array<Vec3, 8>& p) { return hex_jacobians(p).scaled_jacobian; }

}  // namespace volmesh
