#pragma once
// Exact checks of a tetrahedralization by projection against its input surfaces, in GMP
// rationals: every tet positive, the volumes adding up to the enclosed volume exactly, every
// face shared by at most two tets, and the faces used once covering the input triangles
// exactly (each a coplanar piece of one, their areas adding up to its area).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "volmesh/tet/projection.hpp"

namespace volmesh::tet::testing {

inline mpq_class six_volume(const RationalPoint& a, const RationalPoint& b, const RationalPoint& c,
                            const RationalPoint& d) {
  const mpq_class ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const mpq_class vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const mpq_class wx = d.x - a.x, wy = d.y - a.y, wz = d.z - a.z;
  return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}

inline RationalPoint rational(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

inline Vec3 approximate(const RationalPoint& p) { return {p.x.get_d(), p.y.get_d(), p.z.get_d()}; }

// Whether p is far enough off the plane of abc, in doubles, that the exact test can be
// skipped: a coplanar point's double determinant is rounding noise (p and a rounded to
// doubles, so w off by about 1e-16 of their size), far below this.
inline bool clearly_off_plane(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
  constexpr double kRelative = 1e-9;
  const Vec3 u = b - a, v = c - a, w = p - a;
  return std::abs(u.cross(v).dot(w)) >
         kRelative * u.norm() * v.norm() * (w.norm() + a.norm() + p.norm());
}

// Twice the area of triangle abc projected along the axis where its normal is largest (the
// same axis for every piece of one input triangle), signed.
inline mpq_class projected_area(const RationalPoint& a, const RationalPoint& b,
                                const RationalPoint& c, int axis) {
  const auto u = [&](const RationalPoint& p) { return axis == 0 ? p.y : axis == 1 ? p.z : p.x; };
  const auto v = [&](const RationalPoint& p) { return axis == 0 ? p.z : axis == 1 ? p.x : p.y; };
  return (u(b) - u(a)) * (v(c) - v(a)) - (v(b) - v(a)) * (u(c) - u(a));
}

inline int dominant_axis(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a).cwiseAbs();
  return n.x() >= n.y() && n.x() >= n.z() ? 0 : n.y() >= n.z() ? 1 : 2;
}

// Whether p lies in the closed triangle abc (p coplanar with it), seen along `axis`.
inline bool inside(const RationalPoint& p, const RationalPoint& a, const RationalPoint& b,
                   const RationalPoint& c, int axis) {
  const mpq_class total = projected_area(a, b, c, axis);
  const mpq_class s0 = projected_area(p, b, c, axis), s1 = projected_area(a, p, c, axis),
                  s2 = projected_area(a, b, p, axis);
  const int sign = sgn(total);
  return sgn(s0) * sign >= 0 && sgn(s1) * sign >= 0 && sgn(s2) * sign >= 0;
}

inline void expect_exact_tetrahedralization(const std::vector<ProjectionSurface>& surfaces,
                                            const ProjectionMesh& mesh) {
  ASSERT_EQ(mesh.tets.size(), mesh.tet_region.size());
  mpq_class six_total = 0;
  std::map<std::array<Index, 3>, int> uses;
  Index flat = 0;
  for (const auto& t : mesh.tets) {
    const mpq_class v = six_volume(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]],
                                   mesh.points[t[3]]);
    flat += sgn(v) <= 0;
    six_total += v;
    for (const auto& f : {std::array<Index, 3>{t[0], t[1], t[2]}, {t[0], t[1], t[3]},
                          {t[0], t[2], t[3]}, {t[1], t[2], t[3]}}) {
      std::array<Index, 3> key = f;
      std::sort(key.begin(), key.end());
      ++uses[key];
    }
  }
  EXPECT_EQ(flat, 0) << "tets without positive exact volume";
  EXPECT_TRUE(six_total / 6 == mesh.stats.enclosed_volume)
      << "tets " << mpq_class(six_total / 6).get_d() << " vs enclosed " << mesh.stats.enclosed_volume.get_d();

  // Input triangles, all surfaces, with their rational corners.
  struct Input {
    RationalPoint a, b, c;
    int axis;
    mpq_class area, covered = 0;
    Vec3 da, db, dc;  // in doubles, to skip the planes a face is clearly not in
  };
  std::vector<Input> input;
  for (const ProjectionSurface& s : surfaces)
    for (const auto& t : s.surface.triangles) {
      const Vec3 &a = s.surface.points[t[0]], &b = s.surface.points[t[1]], &c = s.surface.points[t[2]];
      Input in{rational(a), rational(b), rational(c), dominant_axis(a, b, c), 0, 0, a, b, c};
      in.area = abs(projected_area(in.a, in.b, in.c, in.axis));
      input.push_back(in);
    }
  Index over_used = 0, stray = 0;
  for (const auto& [face, n] : uses) {
    over_used += n > 2;
    if (n != 1) continue;
    const RationalPoint &p = mesh.points[face[0]], &q = mesh.points[face[1]], &r = mesh.points[face[2]];
    bool found = false;
    const Vec3 dp = approximate(p), dq = approximate(q), dr = approximate(r);
    for (Input& in : input) {
      if (clearly_off_plane(in.da, in.db, in.dc, dp) || clearly_off_plane(in.da, in.db, in.dc, dq) ||
          clearly_off_plane(in.da, in.db, in.dc, dr))
        continue;
      if (sgn(six_volume(in.a, in.b, in.c, p)) != 0 || sgn(six_volume(in.a, in.b, in.c, q)) != 0 ||
          sgn(six_volume(in.a, in.b, in.c, r)) != 0)
        continue;
      if (!inside(p, in.a, in.b, in.c, in.axis) || !inside(q, in.a, in.b, in.c, in.axis) ||
          !inside(r, in.a, in.b, in.c, in.axis))
        continue;
      in.covered += abs(projected_area(p, q, r, in.axis));
      found = true;
      break;
    }
    stray += !found;
  }
  EXPECT_EQ(over_used, 0) << "faces shared by more than two tets";
  EXPECT_EQ(stray, 0) << "faces used once that lie on no input triangle";
  // Interfaces between regions are inner faces; the outermost surfaces are covered exactly.
  Index uncovered = 0;
  std::size_t k = 0;
  for (const ProjectionSurface& s : surfaces)
    for (std::size_t t = 0; t < s.surface.triangles.size(); ++t, ++k)
      if (s.outermost) uncovered += input[k].covered != input[k].area;
  EXPECT_EQ(uncovered, 0) << "outer input triangles not exactly covered by boundary faces";
}

}  // namespace volmesh::tet::testing
