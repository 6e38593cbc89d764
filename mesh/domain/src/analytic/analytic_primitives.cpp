// Placing primitives: constructors in world coordinates, rigid motions, world bounds and
// the validity checks the domain runs on user-built primitives.
#include <cmath>
#include <limits>
#include <utility>

#include "analytic_shapes.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh {
namespace {

// A rotation whose third column is `axis`. A coordinate axis gives a signed permutation,
// so that world coordinates stay exact in the local frame.
Eigen::Matrix3d frame_with_z(const Vec3& axis) {
  const Vec3 z = axis.normalized();
  int k = 0;
  z.cwiseAbs().maxCoeff(&k);
  const Vec3 helper = Vec3::Unit((k + 1) % 3);
  const Vec3 x = (helper - helper.dot(z) * z).normalized();
  Eigen::Matrix3d r;
  r << x, z.cross(x), z;
  return r;
}

Primitive placed(Shape shape, const Eigen::Matrix3d& rotation, const Vec3& translation,
                 std::string name) {
  return {std::move(shape), Rigid{rotation, translation}, std::move(name)};
}

}  // namespace

Rigid operator*(const Rigid& outer, const Rigid& inner) {
  return {outer.rotation * inner.rotation, outer.rotation * inner.translation + outer.translation};
}

Eigen::Matrix3d euler_zxz(double phi, double theta, double psi) {
  return (Eigen::AngleAxisd(phi, Vec3::UnitZ()) * Eigen::AngleAxisd(theta, Vec3::UnitX()) *
          Eigen::AngleAxisd(psi, Vec3::UnitZ()))
      .toRotationMatrix();
}

Primitive sphere(const Vec3& centre, double radius, std::string name) {
  return placed(Sphere{radius}, Eigen::Matrix3d::Identity(), centre, std::move(name));
}

Primitive box(const Vec3& lo, const Vec3& hi, std::string name) {
  return placed(Box{lo, hi}, Eigen::Matrix3d::Identity(), Vec3::Zero(), std::move(name));
}

Primitive cylinder(const Vec3& base, const Vec3& top, double radius, std::string name) {
  const Eigen::Matrix3d r = frame_with_z(top - base);
  const Vec3 axis = r.col(2);
  // Origin at the foot of the world origin on the axis: local z is then axis . p.
  return placed(Cylinder{radius, axis.dot(base), axis.dot(top)}, r,
                base - axis.dot(base) * axis, std::move(name));
}

Primitive torus(const Vec3& centre, const Vec3& axis, double major, double minor,
                std::string name) {
  return placed(Torus{major, minor}, frame_with_z(axis), centre, std::move(name));
}

Primitive ellipsoid(const Vec3& centre, const Vec3& semi_axes, std::string name) {
  return placed(Ellipsoid{semi_axes}, Eigen::Matrix3d::Identity(), centre, std::move(name));
}

Primitive half_space(const Vec3& point, const Vec3& normal, std::string name) {
  const Eigen::Matrix3d r = frame_with_z(normal);
  return placed(HalfSpace{r.col(2).dot(point)}, r, Vec3::Zero(), std::move(name));
}

Primitive moved(Primitive p, const Rigid& motion) {
  p.frame = motion * p.frame;
  return p;
}

namespace analytic {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Box3 around(const Vec3& centre, const Vec3& extent) { return {centre - extent, centre + extent}; }

// Half-extent, along each world axis, of a disc of radius r with unit normal `axis`.
Vec3 disc_extent(const Vec3& axis, double r) {
  return r * (Vec3::Ones() - axis.cwiseProduct(axis)).cwiseMax(0.0).cwiseSqrt();
}

struct BoundsOf {
  const Rigid& f;
  Box3 operator()(const Sphere& s) const {
    return around(f.translation, Vec3::Constant(s.radius));
  }
  Box3 operator()(const Box& b) const {
    return around(f.rotation * (0.5 * (b.lo + b.hi)) + f.translation,
                  f.rotation.cwiseAbs() * (0.5 * (b.hi - b.lo)));
  }
  Box3 operator()(const Cylinder& c) const {
    const Vec3 axis = f.rotation.col(2);
    const Vec3 p0 = f.rotation * Vec3(0, 0, c.z0) + f.translation;
    const Vec3 p1 = f.rotation * Vec3(0, 0, c.z1) + f.translation;
    const Vec3 e = disc_extent(axis, c.radius);
    return {p0.cwiseMin(p1) - e, p0.cwiseMax(p1) + e};
  }
  Box3 operator()(const Torus& t) const {
    return around(f.translation,
                  disc_extent(f.rotation.col(2), t.major) + Vec3::Constant(t.minor));
  }
  Box3 operator()(const Ellipsoid& e) const {
    // Support function of the ellipsoid along each world axis.
    return around(f.translation,
                  (f.rotation * e.semi_axes.asDiagonal()).rowwise().norm());
  }
  Box3 operator()(const HalfSpace&) const {
    return {Vec3::Constant(-kInf), Vec3::Constant(kInf)};
  }
};

std::string describe(const Primitive& p, int index) {
  static const char* const kNames[] = {"sphere", "box", "cylinder", "torus", "ellipsoid",
                                       "half-space"};
  return "analytic domain: primitive " + std::to_string(index) + " '" + p.name + "' (" +
         kNames[p.shape.index()] + ")";
}

bool positive(double x) { return std::isfinite(x) && x > 0.0; }

struct ShapeProblem {  // nullptr when the shape is valid
  const char* operator()(const Sphere& s) const {
    return positive(s.radius) ? nullptr : "radius must be positive and finite";
  }
  const char* operator()(const Box& b) const {
    return b.lo.allFinite() && b.hi.allFinite() && (b.lo.array() < b.hi.array()).all()
               ? nullptr
               : "corners must be finite with lo < hi";
  }
  const char* operator()(const Cylinder& c) const {
    if (!positive(c.radius)) return "radius must be positive and finite";
    return std::isfinite(c.z0) && std::isfinite(c.z1) && c.z0 < c.z1
               ? nullptr
               : "caps must be finite and distinct";
  }
  const char* operator()(const Torus& t) const {
    return positive(t.minor) && positive(t.major) && t.major > t.minor
               ? nullptr
               : "radii must be finite with major > minor > 0";
  }
  const char* operator()(const Ellipsoid& e) const {
    return e.semi_axes.allFinite() && (e.semi_axes.array() > 0.0).all()
               ? nullptr
               : "semi-axes must be positive and finite";
  }
  const char* operator()(const HalfSpace& h) const {
    return std::isfinite(h.offset) ? nullptr : "offset must be finite";
  }
};

}  // namespace

Box3 world_bounds(const Primitive& prim) { return std::visit(BoundsOf{prim.frame}, prim.shape); }

void validate(const Primitive& prim, int index) {
  // RᵀR may differ from the identity by the rounding of a rotation built from angles, not
  // more.
  constexpr double kOrthonormal = 1e-9;
  const Rigid& f = prim.frame;
  const bool rigid = f.rotation.allFinite() && f.translation.allFinite() &&
                     (f.rotation.transpose() * f.rotation - Eigen::Matrix3d::Identity())
                             .cwiseAbs()
                             .maxCoeff() < kOrthonormal &&
                     f.rotation.determinant() > 0.0;
  if (!rigid) throw InputError(describe(prim, index) + ": frame is not a rigid motion");
  if (const char* problem = std::visit(ShapeProblem{}, prim.shape))
    throw InputError(describe(prim, index) + ": " + problem);
}

}  // namespace analytic
}  // namespace volmesh
