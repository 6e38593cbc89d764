#pragma once
// Per-shape geometry in the local frame: the sign test used by region(), the unit outward
// gradient, a distance estimate, and the intersection of a line with the solid. The sign
// tests are inline because region() runs them ~10^7 times per mesh.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "volmesh/domain/analytic.hpp"

namespace volmesh::analytic {

// Where a point (or the open piece of a line) lies relative to one closed solid.
enum class Side : std::uint8_t { out, in, on };

inline Side side_of(double value) {
  return value < 0.0 ? Side::in : value == 0.0 ? Side::on : Side::out;
}

// Sign tests: negative inside, zero exactly on the surface, square roots avoided where
// possible. The quadric and slab line solvers build their equations from the same
// expressions, so that an end point exactly on a surface is exactly a root.
inline double sign_value(const Sphere& s, const Vec3& p) {
  return p.squaredNorm() - s.radius * s.radius;
}
inline double sign_value(const Box& b, const Vec3& p) {
  return std::max((b.lo - p).maxCoeff(), (p - b.hi).maxCoeff());
}
inline double sign_value(const Cylinder& c, const Vec3& p) {
  const double radial = p.x() * p.x() + p.y() * p.y() - c.radius * c.radius;
  return std::max(radial, std::max(c.z0 - p.z(), p.z() - c.z1));
}
inline double sign_value(const Torus& t, const Vec3& p) {
  const double ring = std::sqrt(p.x() * p.x() + p.y() * p.y()) - t.major;
  return ring * ring + p.z() * p.z() - t.minor * t.minor;
}
inline double sign_value(const Ellipsoid& e, const Vec3& p) {
  return p.cwiseQuotient(e.semi_axes).squaredNorm() - 1.0;
}
inline double sign_value(const HalfSpace& h, const Vec3& p) { return p.z() - h.offset; }

// R^T (p - t) written out: it runs per primitive on every query, and Eigen's general
// product is hundreds of calls in the unoptimised test builds (identical code when optimised).
inline Vec3 to_local(const Rigid& frame, const Vec3& p) {
  const Eigen::Matrix3d& r = frame.rotation;
  const double x = p.x() - frame.translation.x(), y = p.y() - frame.translation.y(),
               z = p.z() - frame.translation.z();
  return Vec3(r(0, 0) * x + r(1, 0) * y + r(2, 0) * z, r(0, 1) * x + r(1, 1) * y + r(2, 1) * z,
              r(0, 2) * x + r(1, 2) * y + r(2, 2) * z);
}

inline Side classify_local(const Shape& shape, const Vec3& local) {
  return side_of(std::visit([&](const auto& s) { return sign_value(s, local); }, shape));
}
inline Side classify(const Primitive& prim, const Vec3& p) {
  return classify_local(prim.shape, to_local(prim.frame, p));
}

// Whether a box and a point, or the box around a segment, do not meet.
inline bool apart(const Box3& box, const Vec3& p) {
  return (p.array() < box.lo.array()).any() || (p.array() > box.hi.array()).any();
}
inline bool apart(const Box3& box, const Vec3& a, const Vec3& b) {
  return (a.cwiseMax(b).array() < box.lo.array()).any() ||
         (a.cwiseMin(b).array() > box.hi.array()).any();
}

// Unit outward normal at the surface point nearest to `local`: the gradient of the signed
// distance where it exists, a fixed unit vector where it does not (e.g. at a centre).
Vec3 gradient(const Shape& shape, const Vec3& local);
// Signed distance to the surface (exact except for the ellipsoid: first order there).
double distance(const Shape& shape, const Vec3& local);
// World box around the primitive (infinite for a half-space).
Box3 world_bounds(const Primitive& prim);
// Throws InputError naming the primitive when its shape or frame is invalid.
void validate(const Primitive& prim, int index);

// Intersection of the line a + t (b - a) with a primitive: the side at t -> -inf (or at the
// start of the searched range) and the sorted parameters where it changes, with the world
// outward normal there. An event whose `after` equals the side before it is a touch.
struct LineEvent {
  double t;
  Side after;
  Vec3 normal;
};
struct LineHits {
  Side start = Side::out;
  int count = 0;
  std::array<LineEvent, 4> events;  // the torus has at most 4 roots

  void add(double t, Side after, const Vec3& normal) { events[count++] = {t, after, normal}; }
};
// Parameters outside [-kSearchMargin, 1 + kSearchMargin] may be omitted (the torus searches
// only there); the closed-form solvers return every root of the line.
inline constexpr double kSearchMargin = 1e-6;
// a and b in the primitive's local frame; normals are returned in world coordinates.
LineHits line_hits(const Primitive& prim, const Vec3& a_local, const Vec3& b_local);

// Per-shape line solvers in the local frame, with local normals (line_hits rotates them).
LineHits line_hits(const Sphere& s, const Vec3& a, const Vec3& d);
LineHits line_hits(const Box& b, const Vec3& a, const Vec3& d);
LineHits line_hits(const Cylinder& c, const Vec3& a, const Vec3& d);
LineHits line_hits(const Torus& t, const Vec3& a, const Vec3& d);
LineHits line_hits(const Ellipsoid& e, const Vec3& a, const Vec3& d);
LineHits line_hits(const HalfSpace& h, const Vec3& a, const Vec3& d);

}  // namespace volmesh::analytic
