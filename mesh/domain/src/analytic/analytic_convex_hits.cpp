// Closed-form line intersections of the convex shapes: quadratics for the round surfaces,
// slab clipping for planes. Each equation is the shape's sign value along the line.
#include <limits>

#include "analytic_chord.hpp"

namespace volmesh::analytic {
namespace {

const Vec3 kX = Vec3::UnitX(), kY = Vec3::UnitY(), kZ = Vec3::UnitZ();

}  // namespace

LineHits line_hits(const Sphere& s, const Vec3& a, const Vec3& d) {
  Chord c;
  c.clip_quadric(d.squaredNorm(), 2.0 * a.dot(d), a.squaredNorm() - s.radius * s.radius,
                 [&](double t) { return gradient(s, a + t * d); });
  return c.hits();
}

LineHits line_hits(const Ellipsoid& e, const Vec3& a, const Vec3& d) {
  // In coordinates scaled by the semi-axes the ellipsoid is the unit sphere.
  const Vec3 au = a.cwiseQuotient(e.semi_axes), du = d.cwiseQuotient(e.semi_axes);
  Chord c;
  c.clip_quadric(du.squaredNorm(), 2.0 * au.dot(du), au.squaredNorm() - 1.0,
                 [&](double t) { return gradient(e, a + t * d); });
  return c.hits();
}

LineHits line_hits(const Box& b, const Vec3& a, const Vec3& d) {
  Chord c;
  c.clip_slab(a.x(), d.x(), b.lo.x(), b.hi.x(), -kX, kX);
  c.clip_slab(a.y(), d.y(), b.lo.y(), b.hi.y(), -kY, kY);
  c.clip_slab(a.z(), d.z(), b.lo.z(), b.hi.z(), -kZ, kZ);
  return c.hits();
}

LineHits line_hits(const Cylinder& cyl, const Vec3& a, const Vec3& d) {
  Chord c;
  c.clip_slab(a.z(), d.z(), cyl.z0, cyl.z1, -kZ, kZ);
  c.clip_quadric(d.x() * d.x() + d.y() * d.y(), 2.0 * (a.x() * d.x() + a.y() * d.y()),
                 a.x() * a.x() + a.y() * a.y() - cyl.radius * cyl.radius, [&](double t) {
                   const Vec3 p = a + t * d;
                   return Vec3(p.x(), p.y(), 0.0).normalized();
                 });
  return c.hits();
}

LineHits line_hits(const HalfSpace& h, const Vec3& a, const Vec3& d) {
  Chord c;
  c.clip_slab(a.z(), d.z(), -std::numeric_limits<double>::infinity(), h.offset, -kZ, kZ);
  return c.hits();
}

}  // namespace volmesh::analytic
