// Closest surface points of the analytic shapes in their local frames.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "volmesh/domain/analytic_closest.hpp"

namespace volmesh {
namespace {

using Plane = std::array<double, 2>;

// Root s of Σ (n_i / (s + r_i))² = 1 by bisection until the bracket stops shrinking in
// floating point: Eberly, "Distance from a point to an ellipse, an ellipsoid, or a
// hyperellipsoid" (Geometric Tools), robust where Newton's method is not.
template <int N>
double ellipse_root(const std::array<double, N>& r, const std::array<double, N>& n, double g) {
  double s0 = n[N - 1] - 1.0;  // r[N-1] == 1
  double len = 0.0;
  for (double v : n) len = std::hypot(len, v);
  double s1 = g < 0.0 ? 0.0 : len - 1.0;
  double s = 0.5 * (s0 + s1);
  for (int i = 0; i < 2200; ++i) {
    s = 0.5 * (s0 + s1);
    if (s == s0 || s == s1) break;
    double f = -1.0;
    for (int j = 0; j < N; ++j) f += (n[j] / (s + r[j])) * (n[j] / (s + r[j]));
    if (f > 0.0)
      s0 = s;
    else if (f < 0.0)
      s1 = s;
    else
      break;
  }
  return s;
}

// Semi-axes e0 >= e1 > 0, point y0, y1 >= 0.
Plane closest_on_ellipse(double e0, double e1, double y0, double y1) {
  if (y1 > 0.0) {
    if (y0 > 0.0) {
      const double z0 = y0 / e0, z1 = y1 / e1, g = z0 * z0 + z1 * z1 - 1.0;
      if (g == 0.0) return {y0, y1};
      const double r0 = (e0 / e1) * (e0 / e1);
      const double s = ellipse_root<2>({r0, 1.0}, {r0 * z0, z1}, g);
      return {r0 * y0 / (s + r0), y1 / (s + 1.0)};
    }
    return {0.0, e1};
  }
  const double numer0 = e0 * y0, denom0 = e0 * e0 - e1 * e1;
  if (numer0 < denom0) {
    const double x = numer0 / denom0;
    return {e0 * x, e1 * std::sqrt(1.0 - x * x)};
  }
  return {e0, 0.0};
}

// Semi-axes e0 >= e1 >= e2 > 0, point y >= 0 component-wise.
Vec3 closest_on_sorted_ellipsoid(const Vec3& e, const Vec3& y) {
  if (y[2] > 0.0) {
    if (y[1] > 0.0) {
      if (y[0] > 0.0) {
        const Vec3 z = y.cwiseQuotient(e);
        const double g = z.squaredNorm() - 1.0;
        if (g == 0.0) return y;
        const double r0 = (e[0] / e[2]) * (e[0] / e[2]), r1 = (e[1] / e[2]) * (e[1] / e[2]);
        const double s = ellipse_root<3>({r0, r1, 1.0}, {r0 * z[0], r1 * z[1], z[2]}, g);
        return {r0 * y[0] / (s + r0), r1 * y[1] / (s + r1), y[2] / (s + 1.0)};
      }
      const Plane q = closest_on_ellipse(e[1], e[2], y[1], y[2]);
      return {0.0, q[0], q[1]};
    }
    if (y[0] > 0.0) {
      const Plane q = closest_on_ellipse(e[0], e[2], y[0], y[2]);
      return {q[0], 0.0, q[1]};
    }
    return {0.0, 0.0, e[2]};
  }
  // On the plane of the two largest axes: the closest point may leave it (interior points).
  const double denom0 = e[0] * e[0] - e[2] * e[2], denom1 = e[1] * e[1] - e[2] * e[2];
  const double numer0 = e[0] * y[0], numer1 = e[1] * y[1];
  if (numer0 < denom0 && numer1 < denom1) {
    const double x0 = numer0 / denom0, x1 = numer1 / denom1, discr = 1.0 - x0 * x0 - x1 * x1;
    if (discr > 0.0) return {e[0] * x0, e[1] * x1, e[2] * std::sqrt(discr)};
  }
  const Plane q = closest_on_ellipse(e[0], e[1], y[0], y[1]);
  return {q[0], q[1], 0.0};
}

SurfacePoint closest_local(const Ellipsoid& shape, const Vec3& p) {
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return shape.semi_axes[a] > shape.semi_axes[b]; });
  Vec3 e, y;
  for (int i = 0; i < 3; ++i) {
    e[i] = shape.semi_axes[order[i]];
    y[i] = std::abs(p[order[i]]);
  }
  const Vec3 x = closest_on_sorted_ellipsoid(e, y);
  Vec3 q;
  for (int i = 0; i < 3; ++i) q[order[i]] = std::copysign(x[i], p[order[i]]);
  const Vec3 gradient = q.cwiseQuotient(shape.semi_axes.cwiseProduct(shape.semi_axes));
  return {q, gradient.normalized()};
}

SurfacePoint closest_local(const Sphere& shape, const Vec3& p) {
  const double r = p.norm();
  const Vec3 n = r > 0.0 ? Vec3(p / r) : Vec3::UnitX();
  return {shape.radius * n, n};
}

// Outside a convex solid the closest point is the clamped point, the normal towards p.
SurfacePoint outside_convex(const Vec3& p, const Vec3& clamped) {
  return {clamped, (p - clamped).normalized()};
}

SurfacePoint closest_local(const Box& shape, const Vec3& p) {
  const Vec3 clamped = p.cwiseMax(shape.lo).cwiseMin(shape.hi);
  if (clamped != p) return outside_convex(p, clamped);
  int axis = 0;
  bool upper = false;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    for (bool up : {false, true}) {
      const double d = up ? shape.hi[i] - p[i] : p[i] - shape.lo[i];
      if (d < best) best = d, axis = i, upper = up;
    }
  Vec3 q = p, n = Vec3::Zero();
  q[axis] = upper ? shape.hi[axis] : shape.lo[axis];
  n[axis] = upper ? 1.0 : -1.0;
  return {q, n};
}

// Unit radial direction in the xy plane (x where undefined) and the distance from the z axis.
std::pair<Vec3, double> radial(const Vec3& p) {
  const double rho = std::hypot(p.x(), p.y());
  return {rho > 0.0 ? Vec3(p.x() / rho, p.y() / rho, 0.0) : Vec3::UnitX(), rho};
}

SurfacePoint closest_local(const Cylinder& shape, const Vec3& p) {
  const auto [e, rho] = radial(p);
  if (rho > shape.radius || p.z() < shape.z0 || p.z() > shape.z1)
    return outside_convex(p, std::min(rho, shape.radius) * e +
                                 std::clamp(p.z(), shape.z0, shape.z1) * Vec3::UnitZ());
  const double side = shape.radius - rho, bottom = p.z() - shape.z0, top = shape.z1 - p.z();
  if (side <= bottom && side <= top) return {shape.radius * e + p.z() * Vec3::UnitZ(), e};
  if (bottom <= top) return {Vec3(p.x(), p.y(), shape.z0), -Vec3::UnitZ()};
  return {Vec3(p.x(), p.y(), shape.z1), Vec3::UnitZ()};
}

SurfacePoint closest_local(const Torus& shape, const Vec3& p) {
  const Vec3 ring = shape.major * radial(p).first;
  const Vec3 v = p - ring;
  const double len = v.norm();
  const Vec3 n = len > 0.0 ? Vec3(v / len) : radial(p).first;
  return {ring + shape.minor * n, n};
}

SurfacePoint closest_local(const HalfSpace& shape, const Vec3& p) {
  return {Vec3(p.x(), p.y(), shape.offset), Vec3::UnitZ()};
}

}  // namespace

SurfacePoint closest_surface_point(const Primitive& prim, const Vec3& p) {
  const Eigen::Matrix3d& rot = prim.frame.rotation;
  const Vec3 local = rot.transpose() * (p - prim.frame.translation);
  const SurfacePoint s = std::visit([&](const auto& shape) { return closest_local(shape, local); },
                                    prim.shape);
  return {rot * s.point + prim.frame.translation, rot * s.normal};
}

}  // namespace volmesh
