// CSG operations and labelled layers: the region table, and volumes of two overlapping balls.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "test_analytic_support.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/analytic_csg.hpp"

namespace volmesh {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Csg, ContainsEvaluatesTheExpressionOnEveryMask) {
  const Primitive a = sphere(Vec3::Zero(), 1), b = sphere(Vec3::UnitX(), 1),
                  c = sphere(Vec3::UnitY(), 1);
  const Solid s = (Solid(a) | b) - (Solid(c) & a);  // primitives a, b, c, a
  ASSERT_EQ(s.primitives().size(), 4u);
  for (std::uint32_t m = 0; m < 16; ++m) {
    const bool in_a = m & 1, in_b = m & 2, in_c = m & 4, in_a2 = m & 8;
    EXPECT_EQ(s.contains(m), (in_a || in_b) && !(in_c && in_a2)) << m;
  }
}

TEST(Csg, RegionsOfTwoBallsFollowTheOperations) {
  const Primitive a = sphere(Vec3::Zero(), 1), b = sphere(Vec3(1, 0, 0), 1);
  const AnalyticDomain unite = solid_domain(Solid(a) | b);
  const AnalyticDomain intersect = solid_domain(Solid(a) & b);
  const AnalyticDomain subtract = solid_domain(Solid(a) - b);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1.5, 2.5);
  for (int s = 0; s < 2000; ++s) {
    const Vec3 p(u(rng), u(rng) - 0.5, u(rng) - 0.5);
    const bool in_a = p.norm() < 1, in_b = (p - Vec3::UnitX()).norm() < 1;
    EXPECT_EQ(unite.region(p), in_a || in_b);
    EXPECT_EQ(intersect.region(p), in_a && in_b);
    EXPECT_EQ(subtract.region(p), in_a && !in_b);
  }
  // Crossings only where the solid's boundary is: through the middle of the union, the
  // balls' inner surfaces are not crossed.
  const auto c = unite.crossings(Vec3(-2, 0, 0), Vec3(3, 0, 0));
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].t, 0.2, 1e-15);
  EXPECT_NEAR(c[1].t, 0.8, 1e-15);
}

TEST(Csg, VolumesOfTwoOverlappingBalls) {
  // Unit balls with centres 1 apart overlap in a lens of volume pi (4R + d)(2R - d)^2 / 12.
  const Primitive a = sphere(Vec3::Zero(), 1), b = sphere(Vec3(1, 0, 0), 1);
  const double ball = 4 * kPi / 3, lens = kPi * 5.0 / 12.0;
  test::expect_region_volumes(solid_domain(Solid(a) & b), {{1, lens}}, 40000, 100, 2e-3);
  test::expect_region_volumes(solid_domain(Solid(a) | b), {{1, 2 * ball - lens}}, 40000, 100,
                              2e-3);
  test::expect_region_volumes(solid_domain(Solid(a) - b), {{1, ball - lens}}, 40000, 100, 2e-3);
  // Multi-material: each ball alone (labels 1, 2) and the lens (3).
  test::expect_region_volumes(multi_material_domain({a, b}),
                              {{1, ball - lens}, {2, ball - lens}, {3, lens}}, 40000, 100, 2e-3);
}

TEST(Csg, LaterLayersWinWhereLayersOverlap) {
  const AnalyticDomain d = layered_domain({{sphere(Vec3::Zero(), 1), 5},
                                           {box(Vec3::Zero(), Vec3::Constant(2)), 3}});
  EXPECT_EQ(d.region(Vec3(0.5, 0.5, 0.5)), 3);
  EXPECT_EQ(d.region(Vec3(-0.5, 0, 0)), 5);
  EXPECT_EQ(d.region(Vec3(1.5, 1.5, 1.5)), 3);
  EXPECT_EQ(d.regions(), (std::vector<Index>{3, 5}));
  EXPECT_THROW(layered_domain({{sphere(Vec3::Zero(), 1), 0}}), InputError);
}

}  // namespace
}  // namespace volmesh
