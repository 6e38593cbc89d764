#include "volmesh/geometry/polygon_split.hpp"

#include <Eigen/Core>

#include "volmesh/core/geometry.hpp"
#include "volmesh/core/tri_surface.hpp"
#include "volmesh/geometry/self_intersections.hpp"

namespace volmesh {
namespace {

// Ear clipping in the plane normal to the polygon's area vector; each step cuts the convex ear
// with the best shape (area over the sum of squared edges), so that no vertex of the
// remaining polygon lies in it. Empty when no ear is found (a degenerate polygon).
std::vector<std::array<int, 3>> ear_clip(const std::vector<Vec3>& points, std::span<const Index> loop) {
  const int n = static_cast<int>(loop.size());
  const Vec3 normal = polygon_geometry(points, loop).area_vector;
  const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.normalized().cross(e1);
  std::vector<Eigen::Vector2d> p(n);
  for (int k = 0; k < n; ++k) p[k] = {points[loop[k]].dot(e1), points[loop[k]].dot(e2)};
  const auto cross = [&](int a, int b, int c) {
    const Eigen::Vector2d u = p[b] - p[a], v = p[c] - p[a];
    return u.x() * v.y() - u.y() * v.x();
  };
  std::vector<int> left(n);
  for (int k = 0; k < n; ++k) left[k] = k;
  std::vector<std::array<int, 3>> triangles;
  while (left.size() > 3) {
    const int m = static_cast<int>(left.size());
    int best = -1;
    double best_shape = 0.0;
    for (int i = 0; i < m; ++i) {
      const int a = left[(i + m - 1) % m], b = left[i], c = left[(i + 1) % m];
      const double area = cross(a, b, c);
      if (area <= 0.0) continue;
      bool empty = true;
      for (int v : left)
        if (v != a && v != b && v != c && cross(a, b, v) >= 0.0 && cross(b, c, v) >= 0.0 &&
            cross(c, a, v) >= 0.0)
          empty = false;
      const double shape = area / ((p[b] - p[a]).squaredNorm() + (p[c] - p[b]).squaredNorm() +
                                   (p[a] - p[c]).squaredNorm());
      if (empty && shape > best_shape) {
        best = i;
        best_shape = shape;
      }
    }
    if (best < 0) return {};
    triangles.push_back({left[(best + m - 1) % m], left[best], left[(best + 1) % m]});
    left.erase(left.begin() + best);
  }
  triangles.push_back({left[0], left[1], left[2]});
  return triangles;
}

// True when two of the triangles meet in more than a shared vertex or edge, by CGAL's exact
// predicates.
bool triangles_cross(const std::vector<Vec3>& points, std::span<const Index> loop,
                     const std::vector<std::array<int, 3>>& triangles) {
  TriSurface s;
  Vec3 average = Vec3::Zero();
  for (Index v : loop) {
    s.points.push_back(points[v]);
    average += points[v];
  }
  s.points.push_back(average / static_cast<double>(loop.size()));
  for (const auto& t : triangles) s.triangles.push_back({t[0], t[1], t[2]});
  return !find_self_intersections(s, 1).empty();
}

}  // namespace

std::vector<std::array<int, 3>> fan_triangles(std::size_t n) {
  std::vector<std::array<int, 3>> out;
  for (std::size_t k = 0; k < n; ++k)
    out.push_back({static_cast<int>(k), static_cast<int>((k + 1) % n), static_cast<int>(n)});
  return out;
}

PolygonSplit split_polygon(const std::vector<Vec3>& points, std::span<const Index> loop) {
  PolygonSplit out;
  if (loop.size() <= 3 || fan_is_proper(points, loop)) return out;
  // A warped face whose projection folds may still have an ear clipping or a fan that does
  // not cross itself in space.
  out.triangles = ear_clip(points, loop);
  if (!out.triangles.empty() && !triangles_cross(points, loop, out.triangles)) return out;
  out.triangles.clear();
  out.folded = triangles_cross(points, loop, fan_triangles(loop.size()));
  return out;
}

}  // namespace volmesh
