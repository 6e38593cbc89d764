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

// The segment of `line` (at least two points) nearest p, as the index of its end (1 for the
// first), and its point nearest p; the first of equally near segments.
struct NearestSegment {
  std::size_t end = 1;
  Vec3 point;
};

inline NearestSegment nearest_segment(const Vec3& p, const std::vector<Vec3>& line) {
  NearestSegment best{1, closest_on_segment(p, line[0], line[1])};
  double least = (p - best.point).squaredNorm();
  for (std::size_t i = 2; i < line.size(); ++i) {
    const Vec3 q = closest_on_segment(p, line[i - 1], line[i]);
    const double d = (p - q).squaredNorm();
    if (d < least) {
      least = d;
      best = {i, q};
    }
  }
  return best;
}

// The point of `line` (at least one point) nearest p.
inline Vec3 closest_on_polyline(const Vec3& p, const std::vector<Vec3>& line) {
  return line.size() == 1 ? line.front() : nearest_segment(p, line).point;
}

// The unit direction of `line` (at least two points) at its point nearest p: its segment's there
// or, where that point is a vertex joining two segments (a closed line's ends join), the mean of
// theirs.
inline Vec3 polyline_tangent(const Vec3& p, const std::vector<Vec3>& line) {
  const auto [nearest, at] = nearest_segment(p, line);
  const auto direction = [&](std::size_t i) { return (line[i] - line[i - 1]).normalized(); };
  const std::size_t last = line.size() - 1;
  const bool closed = last > 1 && line.front() == line.back();
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
