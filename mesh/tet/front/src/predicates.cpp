#include "predicates.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh::tet::front {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P = K::Point_3;

// |det(b - a, c - a, q - a)| / (|(b - a) x (c - a)| |q - a|) below this: q nearly in the
// plane of abc (the sine of the angle between aq and the plane).
constexpr double kNearlyFlat = 1e-6;

P cg(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

bool is_one_of(Index id, const Corner* c, int n) {
  for (int i = 0; i < n; ++i)
    if (c[i].id == id) return true;
  return false;
}

// Whether the closed segment pq meets the closed triangle t, exactly. Off the triangle's plane
// it is CGAL's test written with orientations only, which CGAL filters statically: pq crosses
// the plane in one point, inside the closed triangle iff the three turns of pq about its edges
// do not have both signs. In the plane, CGAL's own coplanar test.
bool segment_meets_triangle(const Vec3& p, const Vec3& q, const std::array<Corner, 3>& t) {
  const P a = cg(t[0].p), b = cg(t[1].p), c = cg(t[2].p), pp = cg(p), qq = cg(q);
  const CGAL::Orientation op = CGAL::orientation(a, b, c, pp), oq = CGAL::orientation(a, b, c, qq);
  if (op == oq) {
    if (op != CGAL::COPLANAR) return false;
    return CGAL::do_intersect(K::Segment_3(pp, qq), K::Triangle_3(a, b, c));
  }
  const CGAL::Orientation e0 = CGAL::orientation(pp, qq, a, b);
  const CGAL::Orientation e1 = CGAL::orientation(pp, qq, b, c);
  const CGAL::Orientation e2 = CGAL::orientation(pp, qq, c, a);
  const bool some_positive = e0 == CGAL::POSITIVE || e1 == CGAL::POSITIVE || e2 == CGAL::POSITIVE;
  const bool some_negative = e0 == CGAL::NEGATIVE || e1 == CGAL::NEGATIVE || e2 == CGAL::NEGATIVE;
  return !(some_positive && some_negative);
}

// Whether the closed segment s0 s1 meets the closed triangle t beyond their shared corners.
bool segment_meets_triangle(const Corner& s0, const Corner& s1, const std::array<Corner, 3>& t) {
  const bool shared0 = is_one_of(s0.id, t.data(), 3), shared1 = is_one_of(s1.id, t.data(), 3);
  if (shared0 && shared1) return false;  // an edge of the triangle
  if (!shared0 && !shared1) return segment_meets_triangle(s0.p, s1.p, t);
  // One corner a shared: off the plane, the segment leaves it at a; in the plane, it enters
  // the triangle iff its other end q lies in the closed wedge of the triangle at a. Nearly in
  // the plane counts as in it (a conservative refusal): a tet face lying over a front face up
  // to rounding would leave a flat cavity no tet can fill.
  const Corner& q = shared0 ? s1 : s0;
  const Index a_id = shared0 ? s0.id : s1.id;
  int ia = 0;
  while (t[ia].id != a_id) ++ia;
  const Vec3 &a = t[ia].p, &b = t[(ia + 1) % 3].p, &c = t[(ia + 2) % 3].p;
  const Vec3 u = b - a, v = c - a, w = q.p - a, n = u.cross(v);
  const double scale = n.norm() * w.norm();
  if (std::abs(n.dot(w)) > kNearlyFlat * scale) return false;
  const double tolerance = kNearlyFlat * scale * std::max(u.norm(), v.norm());
  return u.cross(w).dot(n) >= -tolerance && w.cross(v).dot(n) >= -tolerance;
}

// Whether p lies in the closed positive tet.
bool in_closed_tet(const std::array<Corner, 4>& t, const Vec3& p) {
  for (int i = 0; i < 4; ++i) {
    std::array<P, 4> q{cg(t[0].p), cg(t[1].p), cg(t[2].p), cg(t[3].p)};
    q[i] = cg(p);
    if (CGAL::orientation(q[0], q[1], q[2], q[3]) == CGAL::NEGATIVE) return false;
  }
  return true;
}

// Whether a plane or a box strictly separates the positive tet from a triangle with no corner
// of its: a sufficient test, exact, far cheaper than the edge-by-edge one.
bool separated(const std::array<Corner, 4>& tet, const std::array<Corner, 3>& tri) {
  for (int a = 0; a < 3; ++a) {
    const double tet_lo = std::min({tet[0].p[a], tet[1].p[a], tet[2].p[a], tet[3].p[a]});
    const double tet_hi = std::max({tet[0].p[a], tet[1].p[a], tet[2].p[a], tet[3].p[a]});
    const double tri_lo = std::min({tri[0].p[a], tri[1].p[a], tri[2].p[a]});
    const double tri_hi = std::max({tri[0].p[a], tri[1].p[a], tri[2].p[a]});
    if (tri_hi < tet_lo || tri_lo > tet_hi) return true;
  }
  const std::array<P, 4> q{cg(tet[0].p), cg(tet[1].p), cg(tet[2].p), cg(tet[3].p)};
  const std::array<P, 3> r{cg(tri[0].p), cg(tri[1].p), cg(tri[2].p)};
  // The triangle beyond one face of the tet: negative with it in place of the opposite corner.
  for (int i = 0; i < 4; ++i) {
    bool beyond = true;
    for (int v = 0; v < 3 && beyond; ++v) {
      std::array<P, 4> s = q;
      s[i] = r[v];
      beyond = CGAL::orientation(s[0], s[1], s[2], s[3]) == CGAL::NEGATIVE;
    }
    if (beyond) return true;
  }
  // The tet on one side of the triangle's plane.
  const CGAL::Orientation side = CGAL::orientation(r[0], r[1], r[2], q[0]);
  if (side == CGAL::COPLANAR) return false;
  for (int k = 1; k < 4; ++k)
    if (CGAL::orientation(r[0], r[1], r[2], q[k]) != side) return false;
  return true;
}

}  // namespace

bool positive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return CGAL::orientation(cg(a), cg(b), cg(c), cg(d)) == CGAL::POSITIVE;
}

bool tet_meets_triangle(const std::array<Corner, 4>& tet, const std::array<Corner, 3>& tri) {
  const bool shares = std::any_of(tri.begin(), tri.end(),
                                  [&](const Corner& v) { return is_one_of(v.id, tet.data(), 4); });
  if (!shares && separated(tet, tri)) return false;
  for (const Corner& v : tri)
    if (!is_one_of(v.id, tet.data(), 4) && in_closed_tet(tet, v.p)) return true;
  for (const auto& e : kTetEdges)
    if (segment_meets_triangle(tet[e[0]], tet[e[1]], tri)) return true;
  for (const auto& f : kTetFaces) {
    const std::array<Corner, 3> face{tet[f[0]], tet[f[1]], tet[f[2]]};
    for (int e = 0; e < 3; ++e)
      if (segment_meets_triangle(tri[e], tri[(e + 1) % 3], face)) return true;
  }
  return false;
}

}  // namespace volmesh::tet::front
