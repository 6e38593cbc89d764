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

// The flat-gap rule's bound: the sine of the angle between a segment from a shared corner and
// a plane through that corner.
constexpr double kFlatGap = 1e-6;

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
  // the triangle iff its other end q lies in the closed wedge of the triangle at a: on c's
  // side of line ab (or on it) and on b's side of line ac (or on it).
  const Corner& q = shared0 ? s1 : s0;
  const Index a_id = shared0 ? s0.id : s1.id;
  int ia = 0;
  while (t[ia].id != a_id) ++ia;
  const P a = cg(t[ia].p), b = cg(t[(ia + 1) % 3].p), c = cg(t[(ia + 2) % 3].p), qq = cg(q.p);
  if (CGAL::orientation(a, b, c, qq) != CGAL::COPLANAR) return false;
  return CGAL::coplanar_orientation(a, b, c, qq) != CGAL::NEGATIVE &&
         CGAL::coplanar_orientation(a, c, b, qq) != CGAL::NEGATIVE;
}

// Whether the segment from the triangle's corner a (shared) to q (not a corner of it) lies
// within a sine of kFlatGap of the triangle's plane and over the triangle, up to the same
// relative bound.
bool nearly_over(const std::array<Corner, 3>& t, Index a_id, const Vec3& q) {
  int ia = 0;
  while (t[ia].id != a_id) ++ia;
  const Vec3 &a = t[ia].p, &b = t[(ia + 1) % 3].p, &c = t[(ia + 2) % 3].p;
  const Vec3 u = b - a, v = c - a, w = q - a, n = u.cross(v);
  const double scale = n.norm() * w.norm();
  if (std::abs(n.dot(w)) > kFlatGap * scale) return false;
  const double tolerance = kFlatGap * scale * std::max(u.norm(), v.norm());
  return u.cross(w).dot(n) >= -tolerance && w.cross(v).dot(n) >= -tolerance;
}

// Whether segment s0 s1, with exactly one corner shared with triangle t, is nearly over it.
bool nearly_over(const Corner& s0, const Corner& s1, const std::array<Corner, 3>& t) {
  const bool shared0 = is_one_of(s0.id, t.data(), 3), shared1 = is_one_of(s1.id, t.data(), 3);
  if (shared0 == shared1) return false;
  return shared0 ? nearly_over(t, s0.id, s1.p) : nearly_over(t, s1.id, s0.p);
}

// Whether `test` (segment, triangle) holds for an edge of the tet against the triangle or an
// edge of the triangle against a face of the tet.
template <class Test>
bool any_edge_against(const std::array<Corner, 4>& tet, const std::array<Corner, 3>& tri,
                      const Test& test) {
  for (const auto& e : kTetEdges)
    if (test(tet[e[0]], tet[e[1]], tri)) return true;
  for (const auto& f : kTetFaces) {
    const std::array<Corner, 3> face{tet[f[0]], tet[f[1]], tet[f[2]]};
    for (int e = 0; e < 3; ++e)
      if (test(tri[e], tri[(e + 1) % 3], face)) return true;
  }
  return false;
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

// Whether a plane through the corners the positive tet and the triangle share (all of space
// when they share none) has one strictly on one side and the other on the other side or in
// it only at the shared corners, or a box separates them: then they meet at most in the hull
// of the shared corners. A sufficient test, exact, far cheaper than the edge-by-edge one.
bool separated(const std::array<Corner, 4>& tet, const std::array<Corner, 3>& tri,
               const std::array<bool, 4>& tet_shared, const std::array<bool, 3>& tri_shared,
               bool shares) {
  if (!shares)
    for (int a = 0; a < 3; ++a) {
      const double tet_lo = std::min({tet[0].p[a], tet[1].p[a], tet[2].p[a], tet[3].p[a]});
      const double tet_hi = std::max({tet[0].p[a], tet[1].p[a], tet[2].p[a], tet[3].p[a]});
      const double tri_lo = std::min({tri[0].p[a], tri[1].p[a], tri[2].p[a]});
      const double tri_hi = std::max({tri[0].p[a], tri[1].p[a], tri[2].p[a]});
      if (tri_hi < tet_lo || tri_lo > tet_hi) return true;
    }
  const std::array<P, 4> q{cg(tet[0].p), cg(tet[1].p), cg(tet[2].p), cg(tet[3].p)};
  const std::array<P, 3> r{cg(tri[0].p), cg(tri[1].p), cg(tri[2].p)};
  // The triangle's other corners beyond a face of the tet through the shared ones: negative
  // with each in place of the face's opposite corner.
  for (int i = 0; i < 4; ++i) {
    if (tet_shared[i]) continue;
    bool beyond = true;
    for (int v = 0; v < 3 && beyond; ++v) {
      if (tri_shared[v]) continue;
      std::array<P, 4> s = q;
      s[i] = r[v];
      beyond = CGAL::orientation(s[0], s[1], s[2], s[3]) == CGAL::NEGATIVE;
    }
    if (beyond) return true;
  }
  // The tet's other corners strictly on one side of the triangle's plane.
  CGAL::Orientation side = CGAL::COPLANAR;
  for (int k = 0; k < 4; ++k) {
    if (tet_shared[k]) continue;
    const CGAL::Orientation o = CGAL::orientation(r[0], r[1], r[2], q[k]);
    if (o == CGAL::COPLANAR || (side != CGAL::COPLANAR && o != side)) return false;
    side = o;
  }
  return true;
}

}  // namespace

bool positive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return CGAL::orientation(cg(a), cg(b), cg(c), cg(d)) == CGAL::POSITIVE;
}

bool tet_meets_triangle(const std::array<Corner, 4>& tet, const std::array<Corner, 3>& tri) {
  std::array<bool, 4> tet_shared{};
  std::array<bool, 3> tri_shared{};
  int shared = 0;
  for (int v = 0; v < 3; ++v) {
    tri_shared[v] = is_one_of(tri[v].id, tet.data(), 4);
    shared += tri_shared[v];
  }
  // A face of the tet: they meet in it only.
  if (shared == 3) return false;
  for (int k = 0; k < 4; ++k) tet_shared[k] = is_one_of(tet[k].id, tri.data(), 3);
  if (separated(tet, tri, tet_shared, tri_shared, shared > 0)) return false;
  for (const Corner& v : tri)
    if (!is_one_of(v.id, tet.data(), 4) && in_closed_tet(tet, v.p)) return true;
  return any_edge_against(tet, tri, [](const Corner& s0, const Corner& s1,
                                       const std::array<Corner, 3>& t) {
    return segment_meets_triangle(s0, s1, t);
  });
}

bool leaves_flat_gap(const std::array<Corner, 4>& tet, const std::array<Corner, 3>& tri) {
  return any_edge_against(tet, tri, [](const Corner& s0, const Corner& s1,
                                       const std::array<Corner, 3>& t) {
    return nearly_over(s0, s1, t);
  });
}

}  // namespace volmesh::tet::front
