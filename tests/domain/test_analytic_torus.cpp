// The torus is the one primitive solved numerically (a quartic along the segment): roots
// close together must both be found.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "volmesh/domain/analytic_csg.hpp"

namespace volmesh {
namespace {

constexpr double kR = 1.0, kr = 0.25;

AnalyticDomain unit_torus() { return solid_domain(torus(Vec3::Zero(), Vec3::UnitZ(), kR, kr)); }

// Exact signed distance to the torus surface, in long double.
long double torus_distance(const Vec3& p) {
  const long double ring = std::hypot((long double)p.x(), (long double)p.y()) - kR;
  return std::hypot(ring, (long double)p.z()) - kr;
}

TEST(AnalyticTorus, EquatorialLineCrossesFourTimesAtTheRadii) {
  const AnalyticDomain d = unit_torus();
  const auto c = d.crossings(Vec3(-2, 0, 0), Vec3(2, 0, 0));
  ASSERT_EQ(c.size(), 4u);
  const double expected[] = {0.1875, 0.3125, 0.6875, 0.8125};  // x = -1.25, -0.75, 0.75, 1.25
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(c[k].t, expected[k], 1e-15);
    EXPECT_EQ(c[k].before, k % 2);
    EXPECT_EQ(c[k].after, 1 - k % 2);
  }
  EXPECT_TRUE(d.crossings(Vec3(0, 0, -2), Vec3(0, 0, 2)).empty());  // through the hole
}

TEST(AnalyticTorus, GrazingLineFindsBothRootsOfEachClosePair) {
  // At height z = sqrt(r^2 - w^2) the line y = 0 meets the tube in pairs |x| = R -+ w:
  // pairs 2w = 4e-6 apart on a segment of length 4, i.e. 1e-6 in t.
  const double w = 2e-6, h = std::sqrt(kr * kr - w * w);
  const AnalyticDomain d = unit_torus();
  const Vec3 a(-2, 0, h), b(2, 0, h);
  const auto c = d.crossings(a, b);
  ASSERT_EQ(c.size(), 4u);
  const double x[] = {-kR - w, -kR + w, kR - w, kR + w};
  for (int k = 0; k < 4; ++k) {
    // The crossing point is only defined to eps / sin(grazing angle) ~ 1e-11 along the line.
    EXPECT_NEAR(c[k].t, (x[k] + 2.0) / 4.0, 1e-10);
    EXPECT_LT(std::abs(torus_distance(c[k].point)), 1e-15);
    EXPECT_EQ(c[k].after, 1 - k % 2);
  }
  EXPECT_EQ(d.region(Vec3(kR, 0, h)), 1);  // between the roots of a pair: inside
}

TEST(AnalyticTorus, LinesJustInsideTheConvexPartCrossTwiceNearTheTangentPoint) {
  const AnalyticDomain d = unit_torus();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int s = 0; s < 200; ++s) {
    // A point on the outer half of the tube (where the torus is convex), its normal, and
    // a tangent direction; the line runs a depth `depth` inside, parallel to the tangent.
    const double phi = 2 * std::numbers::pi * u(rng);
    const double theta = (u(rng) - 0.5) * 0.9 * std::numbers::pi;  // tube angle from outward
    const Vec3 radial(std::cos(phi), std::sin(phi), 0);
    const Vec3 n = std::cos(theta) * radial + std::sin(theta) * Vec3::UnitZ();
    const Vec3 surface = kR * radial + kr * n;
    const Vec3 e1 = n.cross(Vec3::UnitZ()).normalized(), e2 = n.cross(e1);
    const double alpha = 2 * std::numbers::pi * u(rng);
    const Vec3 tangent = std::cos(alpha) * e1 + std::sin(alpha) * e2;
    const double depth = 1e-13 * std::pow(10.0, 7 * u(rng));  // 1e-13 .. 1e-6
    const Vec3 mid = surface - depth * n;
    const Vec3 a = mid - 0.01 * tangent, b = mid + 0.01 * tangent;

    const auto c = d.crossings(a, b);
    ASSERT_EQ(c.size(), 2u) << "line " << s << " depth " << depth;
    EXPECT_EQ(c[0].before, 0);
    EXPECT_EQ(c[0].after, 1);
    EXPECT_EQ(c[1].after, 0);
    EXPECT_LT(c[0].t, 0.5);
    EXPECT_GT(c[1].t, 0.5);
    for (const Crossing& x : c) EXPECT_LT(std::abs(torus_distance(x.point)), 1e-15);
  }
}

}  // namespace
}  // namespace volmesh
