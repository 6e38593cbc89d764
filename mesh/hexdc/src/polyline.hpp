#pragma once
// Closest points on polylines: the creases of features.hpp and the chains following them.
#include <algorithm>
#include <limits>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::hexdc_detail {

inline Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

// The point of `line` (at least one point) nearest p.
inline Vec3 closest_on_polyline(const Vec3& p, const std::vector<Vec3>& line) {
  Vec3 best = line.front();
  double least = (p - best).squaredNorm();
  for (std::size_t i = 1; i < line.size(); ++i) {
    const Vec3 q = closest_on_segment(p, line[i - 1], line[i]);
    const double d = (p - q).squaredNorm();
    if (d < least) {
      least = d;
      best = q;
    }
  }
  return best;
}

// The unit direction of `line` (at least two points) at its point nearest p: its segment's there
// or, where that point is a vertex joining two segments (a closed line's ends join), the mean of
// theirs.
inline Vec3 polyline_tangent(const Vec3& p, const std::vector<Vec3>& line) {
  std::size_t nearest = 1;
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < line.size(); ++i) {
    const double d = (p - closest_on_segment(p, line[i - 1], line[i])).squaredNorm();
    if (d < least) {
      least = d;
      nearest = i;
    }
  }
  const auto direction = [&](std::size_t i) { return (line[i] - line[i - 1]).normalized(); };
  const std::size_t last = line.size() - 1;
  const bool closed = last > 1 && line.front() == line.back();
  const Vec3 at = closest_on_segment(p, line[nearest - 1], line[nearest]);
  Vec3 tangent = direction(nearest);
  if (at == line[nearest] && (nearest < last || closed))
    tangent += direction(nearest < last ? nearest + 1 : 1);
  else if (at == line[nearest - 1] && (nearest > 1 || closed))
    tangent += direction(nearest > 1 ? nearest - 1 : last);
  return tangent.normalized();
}

inline double distance_to_polyline(const Vec3& p, const std::vector<Vec3>& line) {
  return (p - closest_on_polyline(p, line)).norm();
}

// The one-sided Hausdorff distance from polyline `from` to polyline `to`, `from`'s segments
// sampled at `samples` points each.
inline double polyline_excess(const std::vector<Vec3>& from, const std::vector<Vec3>& to,
                              int samples) {
  double worst = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const int n = i == 0 ? 1 : samples;
    for (int k = 1; k <= n; ++k) {
      const Vec3 p = i == 0 ? from[0]
                            : from[i - 1] + (from[i] - from[i - 1]) * (static_cast<double>(k) / n);
      worst = std::max(worst, distance_to_polyline(p, to));
    }
  }
  return worst;
}

}  // namespace volmesh::hexdc_detail
