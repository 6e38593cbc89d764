// Where two interfaces cross inside a face, from their crossings with its sides.
#include <gtest/gtest.h>

#include <cmath>

#include "curve_crossing.hpp"
#include "tangent_point.hpp"

namespace volmesh::cutcell {
namespace {

const Vec3 kPlane(0, 0, 1);

// The circle of radius 0.5 about the origin at angles -pi/2 + a and -pi/2 - b (a cylinder's
// trace, the far end b from the line x = 0), outward normals.
CurveEnds circle(double a, double b) {
  const auto at = [](double angle) { return Vec3(0.5 * std::cos(angle), 0.5 * std::sin(angle), 0.0); };
  const double pi = std::acos(-1.0);
  const Vec3 p = at(-pi / 2 + a), q = at(-pi / 2 - b);
  return {{p, q}, {p.normalized(), q.normalized()}};
}

// The line x = 0 crossed at y = -0.6 and y = -0.4, normals +x on both (the same side).
CurveEnds plane_trace(double half) { return {{Vec3(0, -0.5 - half, 0), Vec3(0, -0.5 + half, 0)}, {Vec3::UnitX(), Vec3::UnitX()}}; }

TEST(CurveCrossing, StraightCurvesCrossExactly) {
  const CurveEnds a{{Vec3(0, 0, 0), Vec3(1, 1, 0)}, {Vec3(1, -1, 0).normalized(), Vec3(1, -1, 0).normalized()}};
  const CurveEnds b{{Vec3(0, 0.8, 0), Vec3(0.8, 0, 0)}, {Vec3(1, 1, 0).normalized(), Vec3(1, 1, 0).normalized()}};
  const std::optional<Vec3> x = crossing_of_curves(a, b, kPlane);
  ASSERT_TRUE(x);
  EXPECT_LT((*x - Vec3(0.4, 0.4, 0)).norm(), 1e-14);
}

// A cylinder crossing the plane x = 0 (builtin:primitives at level 5): the tangent lines'
// least-squares point extrapolates the far crossing's tangent, off by d^2 / 2r; the
// parabola is third order.
TEST(CurveCrossing, CircleThroughALineIsThirdOrder) {
  double previous = 0.0;
  for (const double h : {0.1, 0.05, 0.025}) {
    const CurveEnds a = circle(0.15 * h / 0.5, 0.9 * h / 0.5), b = plane_trace(h / 2);
    const std::optional<Vec3> x = crossing_of_curves(a, b, kPlane);
    ASSERT_TRUE(x) << h;
    const double error = (*x - Vec3(0, -0.5, 0)).norm();
    const std::array<Vec3, 4> s{a.point[0], a.point[1], b.point[0], b.point[1]};
    const std::array<Vec3, 4> n{a.normal[0], a.normal[1], b.normal[0], b.normal[1]};
    const double tangents = (tangent_intersection(s, n, 2) - Vec3(0, -0.5, 0)).norm();
    EXPECT_LT(error, 0.1 * tangents) << h;
    if (previous > 0.0) {
      EXPECT_GT(previous / error, 6.0) << h;
    }
    previous = error;
  }
}

TEST(CurveCrossing, CurvesThatDoNotCrossBetweenTheirEnds) {
  const CurveEnds a{{Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3::UnitY(), Vec3::UnitY()}};
  const CurveEnds b{{Vec3(2, -1, 0), Vec3(2, 1, 0)}, {Vec3::UnitX(), Vec3::UnitX()}};
  EXPECT_FALSE(crossing_of_curves(a, b, kPlane));
  const CurveEnds steep{{Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3::UnitX(), Vec3::UnitY()}};  // leaves at 90°
  EXPECT_FALSE(crossing_of_curves(steep, b, kPlane));
  const CurveEnds parallel{{Vec3(0, 1, 0), Vec3(1, 1, 0)}, {Vec3::UnitY(), Vec3::UnitY()}};
  EXPECT_FALSE(crossing_of_curves(a, parallel, kPlane));
}

}  // namespace
}  // namespace volmesh::cutcell
