// Least-squares points of tangent planes (system (2) of the octree paper) and the
// Kobbelt/EMC sharp-feature test.
#include <gtest/gtest.h>

#include <optional>

#include <Eigen/QR>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tangent_point.hpp"

namespace volmesh::cutcell {
namespace {

TEST(TangentPoint, ThreePlanesMeetAtTheirCorner) {
  const std::vector<Vec3> s{{1, 0.3, 0.7}, {0.2, 2, 0.1}, {0.5, 0.4, 3}};
  const std::vector<Vec3> n{Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  EXPECT_LT((tangent_intersection(s, n) - Vec3(1, 2, 3)).norm(), 1e-12);
}

TEST(TangentPoint, AnUnconstrainedDirectionKeepsTheMassPoint) {
  // Two planes x = 1 and y = 2: the line (1, 2, z); z stays at the points' mean.
  const std::vector<Vec3> s{{1, 0, 0.2}, {0, 2, 0.6}};
  const std::vector<Vec3> n{Vec3::UnitX(), Vec3::UnitY()};
  EXPECT_LT((tangent_intersection(s, n) - Vec3(1, 2, 0.4)).norm(), 1e-12);
  // Relative to another origin, that origin's z.
  EXPECT_LT((tangent_intersection(s, n, Vec3(0, 0, 0.9)) - Vec3(1, 2, 0.9)).norm(), 1e-12);
}

TEST(TangentPoint, NearlyParallelPlanesAreTruncated) {
  // Rows with a singular value below the cutoff are dropped: the point stays within the
  // spread of the planes instead of running off along their intersection.
  const std::vector<Vec3> s{{0, 0, 0}, {0, 0, 0.01}};
  const std::vector<Vec3> n{Vec3(0, 0.001, 1).normalized(), Vec3(0, -0.001, 1).normalized()};
  EXPECT_LT(tangent_intersection(s, n).norm(), 0.02);
}

TEST(TangentPoint, TheFirstPointsKeepTheirPlaneExactly) {
  // The plane x = 1 (the domain's boundary, two points) and three planes of a curved
  // interior interface that disagree on x: all fitted together miss x = 1.
  const std::vector<Vec3> s{{1, 0, 0}, {1, 0.5, 0.2}, {0.9, 0.1, 0.3}, {0.8, 0.2, 0.35}, {0.95, 0.3, 0.1}};
  const std::vector<Vec3> n{Vec3::UnitX(), Vec3::UnitX(), Vec3(0.5, 0, 1).normalized(),
                            Vec3(-0.5, 0, 1).normalized(), Vec3(0, 1, 0.2).normalized()};
  const std::vector<std::uint8_t> level{0, 0, 1, 1, 1};
  EXPECT_GT(std::abs(tangent_intersection(s, n).x() - 1.0), 1e-3);
  const Vec3 p = tangent_intersection_ranked(s, n, level);
  EXPECT_NEAR(p.x(), 1.0, 1e-14);
  // In the plane x = 1 the other planes' least-squares point: n_y y + n_z z = n.s - n_x.
  Eigen::Matrix<double, 3, 2> a;
  Vec3 b;
  for (int k = 0; k < 3; ++k) {
    a.row(k) << n[k + 2].y(), n[k + 2].z();
    b[k] = n[k + 2].dot(s[k + 2]) - n[k + 2].x();
  }
  const Eigen::Vector2d yz = a.colPivHouseholderQr().solve(b);
  EXPECT_NEAR(p.y(), yz[0], 1e-12);
  EXPECT_NEAR(p.z(), yz[1], 1e-12);
  // One level: the plain fit.
  const std::vector<std::uint8_t> one(s.size(), 0);
  EXPECT_EQ(tangent_intersection_ranked(s, n, one), tangent_intersection(s, n));
}

TEST(TangentPoint, LaterLevelsOnlyFitTheDirectionsLeftFree) {
  // Level 0: the plane x = 0; level 1: the plane z = 0.5 and a plane tilted towards x that
  // alone would pull the point off x = 0; level 2: y = 0.25, in the one direction left.
  const std::vector<Vec3> s{{0, 0, 0}, {0.3, 0.3, 0.5}, {0.1, 0, 0.5}, {0.7, 0.25, 0.9}};
  const std::vector<Vec3> n{Vec3::UnitX(), Vec3::UnitZ(), Vec3(1, 0, 1).normalized(), Vec3::UnitY()};
  const std::vector<std::uint8_t> level{0, 1, 1, 2};
  const Vec3 p = tangent_intersection_ranked(s, n, level);
  EXPECT_EQ(p.x(), 0.0);
  EXPECT_NEAR(p.y(), 0.25, 1e-14);
  // Level 1 fits z alone at x = 0: (z - 0.5)^2 + ((z - 0.6) / sqrt 2)^2 least, z = 1.6 / 3.
  EXPECT_NEAR(p.z(), 1.6 / 3.0, 1e-14);
}

TEST(TangentPoint, FewDirectionsTellsPlanesFromCurvedSurfaces) {
  const std::vector<Vec3> box{Vec3::UnitX(), Vec3::UnitX(), -Vec3::UnitY(), Vec3::UnitX(), -Vec3::UnitY()};
  EXPECT_TRUE(few_directions(box, 2));
  EXPECT_FALSE(few_directions(box, 1));
  const std::vector<Vec3> sphere{Vec3(0, 0, 1), Vec3(0.01, 0, 1).normalized()};
  EXPECT_TRUE(few_directions(sphere, 2));
  EXPECT_FALSE(few_directions(sphere, 2, 2));
  EXPECT_TRUE(few_directions(box, 2, 2));
  // A box face grazing the cell: one point on it is enough.
  const std::vector<Vec3> grazed{Vec3::UnitX(), Vec3::UnitX(), -Vec3::UnitY()};
  EXPECT_TRUE(few_directions(grazed, 2, 2));
  const std::vector<Vec3> tilted{Vec3::UnitX(), Vec3::UnitX(), Vec3(0, 1, 1).normalized()};
  EXPECT_FALSE(few_directions(tilted, 2, 2));
}

// A sphere meeting the plane x = 0 along the circle y^2 + z^2 = 1: the normals leave the
// circle's tangent free. Three planes, or one plane alone (two free directions), do not.
TEST(TangentPoint, FreeDirectionIsTheJunctionLine) {
  std::vector<Vec3> normals{Vec3::UnitX(), Vec3::UnitX()};
  for (const double a : {0.60, 0.61, 0.62}) normals.push_back(Vec3(0.0, std::cos(a), std::sin(a)));
  const std::optional<Vec3> line = free_direction(normals);
  ASSERT_TRUE(line);
  EXPECT_NEAR(std::abs(line->dot(Vec3(0.0, -std::sin(0.61), std::cos(0.61)))), 1.0, 1e-3);
  EXPECT_FALSE(free_direction(std::vector<Vec3>{Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()}));
  EXPECT_FALSE(free_direction(std::vector<Vec3>{Vec3::UnitX(), Vec3::UnitX()}));
}

TEST(SharpFeature, SmoothNormalsHaveNone) {
  std::vector<Vec3> s, n;
  for (int k = 0; k < 6; ++k) {
    const double a = 0.2 * k;
    n.push_back(Vec3(std::sin(a) * 0.3, std::cos(a) * 0.3, 1).normalized());
    s.push_back(n.back());
  }
  EXPECT_FALSE(sharp_feature(s, n).has_value());
}

TEST(SharpFeature, BoxEdgeIsAnEdgeOnTheEdgeLine) {
  // Faces x = 1 and y = 1 of a box: the edge (1, 1, z), nearest the points' mean z.
  const std::vector<Vec3> s{{1, 0.2, 0.1}, {1, 0.5, 0.5}, {0.3, 1, 0.3}, {0.6, 1, 0.7}};
  const std::vector<Vec3> n{Vec3::UnitX(), Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitY()};
  const auto f = sharp_feature(s, n);
  ASSERT_TRUE(f.has_value());
  EXPECT_FALSE(f->corner);
  EXPECT_LT((f->point - Vec3(1, 1, 0.4)).norm(), 1e-12);
}

// A layer interface ending on the wall x = 0 (layers6 at level 6): one wall point and two
// interface points whose tangent planes, the interface being curved, meet the wall's along
// no common line. Fitted together the edge point lies 2.5e-7 off the wall, and the wall's
// faces around it are no longer planar; the wall's point fitted first keeps it on the wall.
TEST(SharpFeature, JunctionWithTheBoundaryLiesOnIt) {
  const std::vector<Vec3> s{{0.0, 0.6375, 0.628906}, {0.01875, 0.6375, 0.634229}, {0.01875, 0.620313, 0.62982}};
  const std::vector<Vec3> n{Vec3::UnitX(), Vec3(-0.1809, -0.2714, 0.9453).normalized(),
                            Vec3(-0.1767, -0.2125, 0.9611).normalized()};
  const auto together = sharp_feature(s, n);
  ASSERT_TRUE(together.has_value());
  EXPECT_GT(std::abs(together->point.x()), 1e-8);
  const std::vector<std::uint8_t> level{0, 1, 1};
  const auto ranked = sharp_feature(s, n, {}, level);
  ASSERT_TRUE(ranked.has_value());
  EXPECT_FALSE(ranked->corner);
  EXPECT_LT(std::abs(ranked->point.x()), 1e-15);
  EXPECT_LT((ranked->point - together->point).norm(), 1e-3);
}

TEST(SharpFeature, BoxCornerIsACorner) {
  const std::vector<Vec3> s{{1, 0.2, 0.1}, {0.3, 1, 0.3}, {0.6, 0.2, 1}};
  const std::vector<Vec3> n{Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  const auto f = sharp_feature(s, n);
  ASSERT_TRUE(f.has_value());
  EXPECT_TRUE(f->corner);
  EXPECT_LT((f->point - Vec3(1, 1, 1)).norm(), 1e-12);
}

// The unit sphere and the planes x = 0 and y = 0 meet at (0, 0, 1). Their tangent planes at
// points a tenth away meet 0.01 off it (the sphere's d^2 / 2r); found again beside that
// point, the new planes meet within the square of that distance.
TEST(PlanesNearFeature, OneNewtonStepOntoASphereAndTwoPlanes) {
  const auto near = [](const Vec3& x, const Vec3& d) -> std::optional<std::pair<Vec3, Vec3>> {
    std::optional<std::pair<Vec3, Vec3>> best;
    double nearest = 2.0;
    const auto keep = [&](double t, const Vec3& normal) {
      if (std::abs(t) <= 1.0 && std::abs(normal.dot(d.normalized())) > 0.9 && std::abs(t) < nearest) {
        nearest = std::abs(t);
        best = {x + t * d, normal.dot(d) > 0 ? normal : Vec3(-normal)};
      }
    };
    for (int axis : {0, 1})
      if (d[axis] != 0.0) keep(-x[axis] / d[axis], Vec3::Unit(axis));
    // |x + t d| = 1, the root nearest t = 0.
    const double a = d.squaredNorm(), b = x.dot(d), c = x.squaredNorm() - 1.0;
    if (const double disc = b * b - a * c; disc >= 0.0)
      for (const double t : {(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a})
        keep(t, (x + t * d).normalized());
    return best;
  };
  const double r = 0.1;
  const std::vector<Vec3> s{Vec3(r, r, std::sqrt(1.0 - 2.0 * r * r)), Vec3(0.0, r, 1.0 - r), Vec3(r, 0.0, 1.0 - r)};
  const std::vector<Vec3> n{s[0].normalized(), -Vec3::UnitX(), -Vec3::UnitY()};
  const Vec3 corner = Vec3::UnitZ();
  const Vec3 fitted = tangent_intersection(s, n);
  const double before = (fitted - corner).norm();
  EXPECT_GT(before, 0.005);
  const std::optional<TangentPlanes> planes = planes_near_feature(s, n, fitted, 0.05, 0.01, near);
  ASSERT_TRUE(planes.has_value());
  ASSERT_EQ(planes->points.size(), 3u);
  EXPECT_LT((tangent_intersection(planes->points, planes->normals, fitted) - corner).norm(), 2.0 * before * before);
  // One surface: nothing to meet. A surface not found again: no step.
  EXPECT_FALSE(planes_near_feature(std::vector<Vec3>{s[0]}, std::vector<Vec3>{n[0]}, fitted, 0.05, 0.01, near));
  const auto nowhere = [](const Vec3&, const Vec3&) { return std::optional<std::pair<Vec3, Vec3>>(); };
  EXPECT_FALSE(planes_near_feature(s, n, fitted, 0.05, 0.01, nowhere));
}

}  // namespace
}  // namespace volmesh::cutcell
