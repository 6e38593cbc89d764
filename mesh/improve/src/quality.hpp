#pragma once
// The improver's quality measure (Stellar's "minimum sine"): the smallest sine of a tet's six
// dihedral angles, signed by its volume. 2√2/3 ≈ 0.943 for the regular tet, near 0 for any
// tet with a dihedral angle near 0° or 180°, negative for an inverted tet: it bounds the
// smallest and the largest dihedral angle at once.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh::improve {

// The value of a flat tet none of whose faces has an area.
inline constexpr double kFlatQuality = -std::numeric_limits<double>::max();

// The face of kTetFaces opposite each corner.
inline constexpr std::array<int, 4> kFaceOpposite{2, 3, 1, 0};

// A change must raise the smallest quality it touches by more than this (a fraction of the
// best, 0.943): rounding noise never counts as a gain, so that the passes end.
inline constexpr double kMinGain = 1e-9;

inline bool raises(double fresh, double old) { return fresh > old + kMinGain; }

// The dihedral angle at edge ij has sine 6V |ij| / (|n_k| |n_l|), where k, l are the other
// corners and n_k is twice the area vector of the face opposite corner k.
inline double tet_quality(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const std::array<Vec3, 4> p{p0, p1, p2, p3};
  const double six_volume = (p1 - p0).dot((p2 - p0).cross(p3 - p0));
  std::array<double, 4> twice_area;  // of the face opposite each corner
  for (int k = 0; k < 4; ++k) {
    const auto& f = kTetFaces[kFaceOpposite[k]];
    twice_area[k] = (p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]).norm();
  }
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const auto& e : kTetEdges) {
    // The two corners off edge e name the faces that meet along it.
    int off[2], n = 0;
    for (int k = 0; k < 4; ++k)
      if (k != e[0] && k != e[1]) off[n++] = k;
    const double ratio = (p[e[1]] - p[e[0]]).norm() / (twice_area[off[0]] * twice_area[off[1]]);
    lo = std::min(lo, ratio);
    hi = std::max(hi, ratio);
  }
  if (six_volume > 0.0) return six_volume * lo;
  // Flat or inverted: ordered by how far inverted.
  return std::isfinite(hi) ? six_volume * hi : kFlatQuality;
}

inline double tet_quality(const std::vector<Vec3>& points, const std::array<Index, 4>& t) {
  return tet_quality(points[t[0]], points[t[1]], points[t[2]], points[t[3]]);
}

}  // namespace volmesh::improve
