// The yardstick of the geometric convergence tests: exact distances to the analytic
// surfaces, their sharp edges, surface samples and volumes.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "volmesh/quality/analytic_surfaces.hpp"

namespace volmesh {
namespace {

constexpr double kPi = std::numbers::pi;

// The exact distance from p to one primitive's surface.
double surface_distance(const Primitive& primitive, const Vec3& p) {
  return (closest_surface_point(primitive, p).point - p).norm();
}

// A tilted, shifted frame, so that no test point sits on a symmetry plane by accident.
Primitive tilted(Primitive p) {
  return moved(std::move(p), Rigid{euler_zxz(0.4, 0.7, -0.3), Vec3(0.1, -0.2, 0.05)});
}

// Moving a surface point along its normal by d (less than the smallest radius of curvature)
// puts it exactly |d| from the surface: the distance functions must return |d|.
void expect_offsets_exact(const Primitive& primitive, double max_offset) {
  for (const SurfacePoint& s : sample_surface(primitive, 0.05)) {
    EXPECT_LT(surface_distance(primitive, s.point), 1e-12);
    for (const double d : {-max_offset, -1e-4, 1e-6, 0.3 * max_offset, max_offset})
      ASSERT_NEAR(surface_distance(primitive, s.point + d * s.normal), std::abs(d), 1e-12)
          << primitive.name << " at " << s.point.transpose() << " offset " << d;
  }
}

TEST(AnalyticSurface, SmoothSurfacesOffsetsAreExact) {
  expect_offsets_exact(tilted(sphere(Vec3(0.2, 0, 0), 0.8)), 0.5);
  expect_offsets_exact(tilted(torus(Vec3::Zero(), Vec3(0, 0, 1), 0.7, 0.3)), 0.2);
  // Smallest radius of curvature: 0.45^2 / 1 = 0.2025.
  expect_offsets_exact(tilted(ellipsoid(Vec3::Zero(), Vec3(1.0, 0.7, 0.45))), 0.15);
  expect_offsets_exact(tilted(ellipsoid(Vec3::Zero(), Vec3(0.45, 1.0, 0.7))), 0.15);
}

// Far from the surface and on symmetry planes (the root solve's degenerate cases): against
// the nearest of a dense set of surface samples.
TEST(AnalyticSurface, EllipsoidDistanceMatchesBruteForce) {
  const Vec3 semi(1.0, 0.7, 0.45);
  const Primitive e = ellipsoid(Vec3::Zero(), semi);
  const double spacing = 0.004;
  const std::vector<SurfacePoint> dense = sample_surface(e, spacing);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  std::vector<Vec3> queries = {Vec3(0, 0, 0),      Vec3(0.3, 0, 0),   Vec3(0, 0.2, 0),
                               Vec3(0, 0, 0.1),    Vec3(0.5, 0.3, 0), Vec3(0.9, 0, 0.1),
                               Vec3(2.0, 0, 0),    Vec3(0, 0, -3.0),  Vec3(0.1, 0.6, 0)};
  for (int i = 0; i < 30; ++i)
    queries.emplace_back(coordinate(random), coordinate(random), coordinate(random));
  for (const Vec3& q : queries) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const SurfacePoint& s : dense) nearest = std::min(nearest, (s.point - q).norm());
    const double exact = surface_distance(e, q);
    EXPECT_LE(exact, nearest + 1e-12) << q.transpose();
    EXPECT_GT(exact, nearest - spacing) << q.transpose();
  }
}

TEST(AnalyticSurface, BoxAndCylinderDistancesAndEdges) {
  const Primitive b = box(Vec3(0, -1, 0), Vec3(2, 1, 1));
  EXPECT_DOUBLE_EQ(surface_distance(b, Vec3(1, 0, 0.5)), 0.5);     // inside: nearest face
  EXPECT_DOUBLE_EQ(surface_distance(b, Vec3(3, 2, 0.5)), std::sqrt(2.0));  // outside an edge
  EXPECT_DOUBLE_EQ(sharp_edge_distance(b, Vec3(1, 0, 0.5)), std::hypot(1.0, 0.5));
  EXPECT_DOUBLE_EQ(sharp_edge_distance(b, Vec3(3, 2, 0.5)), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(sharp_edge_distance(b, Vec3(-1, -1, 0)), 1.0);     // beyond a corner
  const Primitive c = cylinder(Vec3(0, 0, -1), Vec3(0, 0, 1), 0.5);
  EXPECT_NEAR(surface_distance(c, Vec3(0.1, 0, 0.8)), 0.2, 1e-15);  // the cap is nearest
  EXPECT_NEAR(surface_distance(c, Vec3(0.3, 0, 0.2)), 0.2, 1e-15);  // the side is
  EXPECT_NEAR(surface_distance(c, Vec3(0.8, 0, 1.4)), 0.5, 1e-15);  // the rim is
  EXPECT_NEAR(sharp_edge_distance(c, Vec3(0.8, 0, 1.4)), 0.5, 1e-15);
  EXPECT_NEAR(sharp_edge_distance(c, Vec3(0, 0, 0)), std::hypot(0.5, 1.0), 1e-15);
  EXPECT_TRUE(std::isinf(sharp_edge_distance(sphere(Vec3::Zero(), 1), Vec3::Zero())));
}

// Samples lie on the surface, include the sharp edges and leave no hole wider than spacing.
TEST(AnalyticSurface, SamplesCoverTheSurface) {
  const double spacing = 0.05;
  for (const Primitive& p : {tilted(sphere(Vec3(0.2, 0, 0), 0.8)),
                             tilted(box(Vec3(0, 0, 0), Vec3(1, 0.5, 0.3))),
                             tilted(cylinder(Vec3(0, 0, 0), Vec3(0, 0, 1), 0.4)),
                             tilted(torus(Vec3::Zero(), Vec3(1, 1, 0), 0.7, 0.3)),
                             tilted(ellipsoid(Vec3::Zero(), Vec3(1.0, 0.7, 0.45)))}) {
    const std::vector<SurfacePoint> samples = sample_surface(p, spacing);
    const std::vector<SurfacePoint> fine = sample_surface(p, spacing / 7.3);
    for (const SurfacePoint& s : samples) {
      ASSERT_LT(surface_distance(p, s.point), 1e-12) << p.name;
      ASSERT_NEAR(s.normal.norm(), 1.0, 1e-12);
      // The normal points out: a step along it leaves the solid's surface by that step.
      ASSERT_NEAR(surface_distance(p, s.point + 1e-3 * s.normal), 1e-3, 1e-9) << p.name;
    }
    double hole = 0.0;
    for (std::size_t i = 0; i < fine.size(); i += 17) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const SurfacePoint& s : samples)
        nearest = std::min(nearest, (s.point - fine[i].point).norm());
      hole = std::max(hole, nearest);
    }
    EXPECT_LT(hole, spacing) << p.name;
    if (std::holds_alternative<Box>(p.shape) || std::holds_alternative<Cylinder>(p.shape)) {
      Index on_edges = 0;
      for (const SurfacePoint& s : samples) on_edges += sharp_edge_distance(p, s.point) < 1e-12;
      EXPECT_GT(on_edges, 20) << p.name;
    }
  }
}

TEST(AnalyticSurface, Volumes) {
  EXPECT_NEAR(solid_volume(torus(Vec3::Zero(), Vec3(0, 0, 1), 0.7, 0.3)),
              2 * kPi * kPi * 0.7 * 0.09, 1e-14);
  EXPECT_NEAR(solid_volume(tilted(ellipsoid(Vec3::Zero(), Vec3(1.0, 0.7, 0.45)))),
              4.0 / 3.0 * kPi * 0.315, 1e-14);
  EXPECT_NEAR(solid_volume(cylinder(Vec3(0, 0, 0), Vec3(0, 3, 4), 0.5)), kPi * 0.25 * 5, 1e-13);
}

}  // namespace
}  // namespace volmesh
