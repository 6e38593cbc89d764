// Boundary data are evaluated on the TRUE boundary: true_boundary_map returns the closest
// point of the domain's outer boundary — exactly for analytic solids (rotated and moved
// ellipsoids and tori included) — and the general normal iteration agrees with it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "volmesh/domain/analytic.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/analytic_csg.hpp"
#include "volmesh/fem/problems.hpp"

namespace volmesh::fem {
namespace {

// Points in a shell of relative thickness `spread` around the unit sphere, mapped by `place`.
template <class Place>
std::vector<Vec3> shell_points(int count, double spread, Place place) {
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / count, phi = 2.399963 * i;
    const double r = std::sqrt(1.0 - z * z);
    const Vec3 dir(r * std::cos(phi), r * std::sin(phi), z);
    const double scale = 1.0 + spread * std::sin(7.1 * i);
    points.push_back(place(scale * dir));
  }
  return points;
}

TEST(TrueBoundary, BallIsRadialProjection) {
  const auto ball = make_builtin_domain("ball");
  const PointMap map = true_boundary_map(*ball);
  for (const Vec3& p : shell_points(200, 0.2, [](const Vec3& x) { return x; })) {
    const Vec3 q = map(p);
    EXPECT_NEAR(q.norm(), 1.0, 1e-12);
    EXPECT_LT(q.cross(p).norm(), 1e-12 * p.norm());
    EXPECT_LT((project_along_normals(*ball, p) - q).norm(), 1e-12);
  }
}

// A closest point q of a smooth surface: on it, with p − q along its normal.
struct SurfaceCheck {
  std::function<double(const Vec3&)> level;  // 0 on the surface, unit-scaled
  std::function<Vec3(const Vec3&)> normal;
};

void expect_closest(const SurfaceCheck& s, const Vec3& p, const Vec3& q, double tolerance) {
  EXPECT_LT(std::abs(s.level(q)), tolerance) << p.transpose();
  EXPECT_LT((p - q).cross(s.normal(q)).norm(), tolerance) << p.transpose();
}

TEST(TrueBoundary, RotatedEllipsoidIsExactAndTheNormalIterationAgrees) {
  const Rigid frame{euler_zxz(0.4, 0.9, -0.3), Vec3(0.2, -0.1, 0.3)};
  const Vec3 axes(1.0, 0.6, 0.35);
  const AnalyticDomain domain = solid_domain(moved(ellipsoid(Vec3::Zero(), axes), frame));
  const auto local = [frame](const Vec3& p) -> Vec3 {
    return frame.rotation.transpose() * (p - frame.translation);
  };
  const SurfaceCheck surface{
      [&](const Vec3& q) { return local(q).cwiseQuotient(axes).squaredNorm() - 1.0; },
      [&](const Vec3& q) -> Vec3 {
        return (frame.rotation * local(q).cwiseQuotient(axes.cwiseProduct(axes))).normalized();
      }};
  const PointMap map = true_boundary_map(domain);
  const auto place = [&](const Vec3& x) -> Vec3 {
    return frame.rotation * x.cwiseProduct(axes) + frame.translation;
  };
  for (const Vec3& p : shell_points(300, 0.1, place)) expect_closest(surface, p, map(p), 1e-10);
  // The normal iteration contracts by about distance × curvature per step: near the tips
  // (radius of curvature 0.12) it is meant for points a few percent of the axes away.
  for (const Vec3& p : shell_points(300, 0.03, place))
    EXPECT_LT((project_along_normals(domain, p) - map(p)).norm(), 1e-10) << p.transpose();
  // Points on the axes' planes take Eberly's special branches.
  for (const Vec3& x : {Vec3(0.5, 0.0, 0.0), Vec3(0.0, 0.2, 0.0), Vec3(0.0, 0.0, 0.1),
                        Vec3(1.3, 0.0, 0.0), Vec3(0.3, 0.2, 0.0), Vec3(0.0, 0.0, 0.0)}) {
    const Vec3 p = frame.rotation * x + frame.translation;
    EXPECT_LT(std::abs(surface.level(map(p))), 1e-10) << x.transpose();
  }
}

TEST(TrueBoundary, TiltedTorusIsExactAndTheNormalIterationAgrees) {
  const Vec3 centre(0.1, 0.2, -0.3), axis = Vec3(1.0, 2.0, 3.0).normalized();
  const double major = 1.0, minor = 0.3;
  const AnalyticDomain domain = solid_domain(torus(centre, axis, major, minor));
  const auto tube_centre = [&](const Vec3& p) -> Vec3 {
    const Vec3 v = p - centre;
    const Vec3 in_plane = v - v.dot(axis) * axis;
    return centre + major * in_plane.normalized();
  };
  const SurfaceCheck surface{
      [&](const Vec3& q) { return (q - tube_centre(q)).norm() - minor; },
      [&](const Vec3& q) -> Vec3 { return (q - tube_centre(q)).normalized(); }};
  const Vec3 e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  const PointMap map = true_boundary_map(domain);
  for (int i = 0; i < 300; ++i) {
    const double theta = 0.37 * i, phi = 1.13 * i, r = minor * (1.0 + 0.3 * std::sin(3.3 * i));
    const Vec3 radial = std::cos(theta) * e1 + std::sin(theta) * e2;
    const Vec3 p =
        centre + major * radial + r * (std::cos(phi) * radial + std::sin(phi) * axis);
    const Vec3 q = map(p);
    expect_closest(surface, p, q, 1e-10);
    EXPECT_LT((project_along_normals(domain, p) - q).norm(), 1e-10) << p.transpose();
  }
}

TEST(TrueBoundary, ThickSphereMapsToTheNearerSurface) {
  const auto shell = make_builtin_domain("thick-sphere");
  const PointMap map = true_boundary_map(*shell);
  const Vec3 dir = Vec3(1.0, -2.0, 0.5).normalized();
  EXPECT_NEAR(map(0.55 * dir).norm(), 0.5, 1e-15);
  EXPECT_NEAR(map(0.45 * dir).norm(), 0.5, 1e-15);
  EXPECT_NEAR(map(0.8 * dir).norm(), 1.0, 1e-15);
  EXPECT_NEAR(map(1.1 * dir).norm(), 1.0, 1e-15);
}

TEST(TrueBoundary, BoxFacesAndCorners) {
  const auto box = make_builtin_domain("box");
  const PointMap map = true_boundary_map(*box);
  EXPECT_EQ(map(Vec3(0.5, 0.97, 0.4)), Vec3(0.5, 1.0, 0.4));
  EXPECT_EQ(map(Vec3(0.02, 0.5, 0.5)), Vec3(0.0, 0.5, 0.5));
  EXPECT_EQ(map(Vec3(1.1, -0.2, 0.5)), Vec3(1.0, 0.0, 0.5));
}

TEST(TrueBoundary, MultiMaterialDomainMapsOntoTheOuterBoundaryOnly) {
  // builtin:primitives: the ball, box and cylinder meet inside; only the interfaces with
  // region 0 are boundary.
  const auto primitives = make_builtin_domain("primitives");
  const PointMap map = true_boundary_map(*primitives);
  const Box3 b = primitives->bounds();
  const double step = 1e-9;
  int tested = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec3 t(std::fmod(0.618034 * i, 1.0), std::fmod(0.754878 * i + 0.1, 1.0),
                 std::fmod(0.569840 * i + 0.3, 1.0));
    const Vec3 p = b.lo + t.cwiseProduct(b.size());
    if (primitives->region(p) == 0) continue;
    const Vec3 q = map(p);
    const Vec3 n = primitives->normal(q);
    EXPECT_NE(primitives->region(q + step * n) == 0, primitives->region(q - step * n) == 0)
        << p.transpose();
    ++tested;
  }
  EXPECT_GT(tested, 100);
}

TEST(TrueBoundary, PointsOnAReflexEdgeOfTheBoundaryMapToThemselves) {
  // builtin:primitives: the box's top (z = 1.2) meets the cylinder's side (radius 0.5, up to
  // z = 1.4) in a circle. Above the top is the cylinder, beside the side the box, yet both
  // surfaces are boundary next to the circle: its points are on the true boundary.
  const auto primitives = make_builtin_domain("primitives");
  const PointMap map = true_boundary_map(*primitives);
  for (int i = 0; i < 16; ++i) {
    const double a = 0.5 * std::numbers::pi * (i + 0.5) / 16.0 - 0.25 * std::numbers::pi;  // x > 0, inside the box
    const Vec3 p(0.5 * std::cos(a), 0.5 * std::sin(a), 1.2);
    EXPECT_LT((map(p) - p).norm(), 1e-15) << p.transpose();
  }
}

}  // namespace
}  // namespace volmesh::fem
