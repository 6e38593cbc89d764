// Signed distances and their gradients (unit outward normals) for each shape, used by
// normal(p) and for normals at the end points of segments.
#include <cmath>

#include "analytic_shapes.hpp"

namespace volmesh::analytic {
namespace {

struct Field {
  double distance;
  Vec3 gradient;
};

// A fixed direction where v vanishes: the gradient is undefined there (e.g. a centre).
Vec3 unit_or_z(const Vec3& v) {
  const double n = v.norm();
  return n > 0.0 ? Vec3(v / n) : Vec3::UnitZ();
}

// Unit vector from the z axis towards p, in the plane z = 0.
Vec3 radial(const Vec3& p) {
  const Vec3 r(p.x(), p.y(), 0.0);
  const double n = r.norm();
  return n > 0.0 ? Vec3(r / n) : Vec3::UnitX();
}

struct FieldAt {
  const Vec3& p;

  Field operator()(const Sphere& s) const { return {p.norm() - s.radius, unit_or_z(p)}; }
  Field operator()(const Box& b) const {
    const Vec3 below = b.lo - p, above = p - b.hi;  // positive outside the face
    const Vec3 outside = above.cwiseMax(0.0) - below.cwiseMax(0.0);
    if (outside != Vec3::Zero()) return {outside.norm(), outside.normalized()};
    int kb = 0, ka = 0;  // inside or on: the nearest face
    const double db = below.maxCoeff(&kb), da = above.maxCoeff(&ka);
    return da >= db ? Field{da, Vec3::Unit(ka)} : Field{db, -Vec3::Unit(kb)};
  }
  Field operator()(const Cylinder& c) const {
    // A 2D box in (distance from the axis, z).
    const double u = std::hypot(p.x(), p.y()) - c.radius;
    const bool top = p.z() - c.z1 >= c.z0 - p.z();
    const double v = top ? p.z() - c.z1 : c.z0 - p.z();
    const Vec3 axial = top ? Vec3::UnitZ() : Vec3(-Vec3::UnitZ());
    if (u > 0.0 && v > 0.0) return {std::hypot(u, v), (u * radial(p) + v * axial).normalized()};
    return u >= v ? Field{u, radial(p)} : Field{v, axial};
  }
  Field operator()(const Torus& t) const {
    // From the nearest point of the tube's centre circle.
    const Vec3 w = (std::hypot(p.x(), p.y()) - t.major) * radial(p) + p.z() * Vec3::UnitZ();
    return {w.norm() - t.minor, unit_or_z(w)};
  }
  Field operator()(const Ellipsoid& e) const {
    // First order: value / |gradient| of |p / semi_axes|^2 - 1.
    const Vec3 g = 2.0 * p.cwiseQuotient(e.semi_axes.cwiseProduct(e.semi_axes));
    const double value = sign_value(e, p), n = g.norm();
    return {n > 0.0 ? value / n : -e.semi_axes.minCoeff(), unit_or_z(g)};
  }
  Field operator()(const HalfSpace& h) const { return {p.z() - h.offset, Vec3::UnitZ()}; }
};

}  // namespace

Vec3 gradient(const Shape& shape, const Vec3& local) {
  return std::visit(FieldAt{local}, shape).gradient;
}

double distance(const Shape& shape, const Vec3& local) {
  return std::visit(FieldAt{local}, shape).distance;
}

}  // namespace volmesh::analytic
