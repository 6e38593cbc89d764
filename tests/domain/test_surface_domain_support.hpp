#pragma once
// Surfaces for the surface-domain and signed-distance tests: boxes with subdivided faces,
// icospheres, meshes from Debian's libcgal-demo, and brute-force references (distance to a
// triangle, generalized winding number) written independently of the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <string>

#include "volmesh/core/tri_surface.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh::surface_test {

// The box [lo, hi], each face an n x n grid of squares split along a diagonal, outward.
inline TriSurface box_surface(const Vec3& lo, const Vec3& hi, int n) {
  TriSurface s;
  std::map<std::array<int, 3>, Index> index;  // grid coordinates 0..n -> point
  const auto point = [&](std::array<int, 3> g) {
    auto [it, fresh] = index.try_emplace(g, s.num_points());
    if (fresh) {
      Vec3 p;
      for (int a = 0; a < 3; ++a)
        p[a] = g[a] == 0 ? lo[a] : g[a] == n ? hi[a] : lo[a] + (hi[a] - lo[a]) * g[a] / n;
      s.points.push_back(p);
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          std::array<std::array<int, 3>, 4> q;
          for (int c = 0; c < 4; ++c) {
            q[c][axis] = side * n;
            q[c][u] = i + (c == 1 || c == 2);
            q[c][v] = j + (c >= 2);
          }
          // (u, v) counter-clockwise seen along +axis: outward on the high side.
          std::array<Index, 4> k{point(q[0]), point(q[1]), point(q[2]), point(q[3])};
          if (side == 0) std::swap(k[1], k[3]);
          s.triangles.push_back({k[0], k[1], k[2]});
          s.triangles.push_back({k[0], k[2], k[3]});
        }
    }
  return s;
}

// The icosahedron inscribed in the unit sphere, each triangle split in four `levels` times,
// new vertices pushed onto the sphere.
inline TriSurface icosphere(int levels) {
  const double f = (1.0 + std::sqrt(5.0)) / 2.0;
  TriSurface s;
  for (const Vec3& p : {Vec3(-1, f, 0), Vec3(1, f, 0), Vec3(-1, -f, 0), Vec3(1, -f, 0),
                        Vec3(0, -1, f), Vec3(0, 1, f), Vec3(0, -1, -f), Vec3(0, 1, -f),
                        Vec3(f, 0, -1), Vec3(f, 0, 1), Vec3(-f, 0, -1), Vec3(-f, 0, 1)})
    s.points.push_back(p.normalized());
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<Index, Index>, Index> middle;
    const auto mid = [&](Index a, Index b) {
      auto [it, fresh] = middle.try_emplace({std::min(a, b), std::max(a, b)}, s.num_points());
      if (fresh) s.points.push_back((s.points[a] + s.points[b]).normalized());
      return it->second;
    };
    std::vector<std::array<Index, 3>> finer;
    for (const auto& t : s.triangles) {
      const Index ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.insert(finer.end(), {{t[0], ab, ca}, {t[1], bc, ab}, {t[2], ca, bc}, {ab, bc, ca}});
    }
    s.triangles = std::move(finer);
  }
  return s;
}

// A closed mesh from libcgal-demo, checked and oriented outward; nullopt if not installed.
inline std::optional<TriSurface> cgal_mesh(const std::string& name) {
  const auto path = std::filesystem::path(VOLMESH_CGAL_DATA) / "meshes" / name;
  if (!std::filesystem::exists(path)) return std::nullopt;
  TriSurface s = read_surface(path);
  check_surface(s, path.string(), {.find_self_intersections = false});
  return s;
}

// Triangles as plain corner coordinates: the brute-force loops below stay fast in debug
// and sanitizer builds.
using Corners = std::array<double, 9>;
inline std::vector<Corners> corners(const TriSurface& s) {
  std::vector<Corners> out;
  for (const auto& t : s.triangles) {
    Corners c;
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) c[3 * k + a] = s.points[t[k]][a];
    out.push_back(c);
  }
  return out;
}

namespace detail {
inline double dot(const double* x, const double* y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}
inline void cross(const double* x, const double* y, double* z) {
  z[0] = x[1] * y[2] - x[2] * y[1];
  z[1] = x[2] * y[0] - x[0] * y[2];
  z[2] = x[0] * y[1] - x[1] * y[0];
}
inline void minus(const double* x, const double* y, double* z) {
  for (int a = 0; a < 3; ++a) z[a] = x[a] - y[a];
}
// Squared distance from p to segment xy.
inline double segment2(const double* p, const double* x, const double* y) {
  double xy[3], xp[3];
  minus(y, x, xy);
  minus(p, x, xp);
  const double t = std::clamp(dot(xp, xy) / dot(xy, xy), 0.0, 1.0);
  double r[3];
  for (int a = 0; a < 3; ++a) r[a] = xp[a] - t * xy[a];
  return dot(r, r);
}
}  // namespace detail

// Distance from p to the nearest triangle: to the plane where p projects inside the
// triangle, else to the nearest side.
inline double distance_to_surface(const std::vector<Corners>& triangles, const Vec3& point) {
  using namespace detail;
  const double p[3] = {point.x(), point.y(), point.z()};
  double best = std::numeric_limits<double>::infinity();
  for (const Corners& c : triangles) {
    const double *a = &c[0], *b = &c[3], *d = &c[6];
    double ab[3], ad[3], n[3], ap[3];
    minus(b, a, ab);
    minus(d, a, ad);
    cross(ab, ad, n);
    minus(p, a, ap);
    const double h = dot(n, ap) / std::sqrt(dot(n, n));
    if (h * h >= best) continue;
    // Inside when p is on the inner side of the three sides' planes through n.
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const double *x = &c[3 * k], *y = &c[3 * ((k + 1) % 3)];
      double xy[3], xp[3], m[3];
      minus(y, x, xy);
      minus(p, x, xp);
      cross(xy, xp, m);
      inside = dot(m, n) >= 0.0;
    }
    const double d2 =
        inside ? h * h : std::min({segment2(p, a, b), segment2(p, b, d), segment2(p, d, a)});
    best = std::min(best, d2);
  }
  return std::sqrt(best);
}

// Generalized winding number (Jacobson et al. 2013): the solid angles of the triangles seen
// from p (Van Oosterom & Strackee), over 4 pi. 1 inside a closed outward surface, 0 outside.
inline double winding_number(const std::vector<Corners>& triangles, const Vec3& point) {
  using namespace detail;
  const double p[3] = {point.x(), point.y(), point.z()};
  double sum = 0.0;
  for (const Corners& c : triangles) {
    double a[3], b[3], d[3], bd[3];
    minus(&c[0], p, a);
    minus(&c[3], p, b);
    minus(&c[6], p, d);
    cross(b, d, bd);
    const double la = std::sqrt(dot(a, a)), lb = std::sqrt(dot(b, b)), ld = std::sqrt(dot(d, d));
    sum += 2.0 *
           std::atan2(dot(a, bd), la * lb * ld + dot(a, b) * ld + dot(a, d) * lb + dot(b, d) * la);
  }
  return sum / (4.0 * std::numbers::pi);
}

}  // namespace volmesh::surface_test
