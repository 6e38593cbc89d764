// AnalyticDomain as a Domain: priority on interfaces, end points on surfaces, segments in a
// face, touches, consistency of crossings with region(), batch queries, normals, errors.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "test_analytic_support.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/analytic_csg.hpp"

namespace volmesh {
namespace {

// The regions along a -> b as crossings describe them must be the regions region() gives.
void expect_consistent(const Domain& d, const Vec3& a, const Vec3& b) {
  const std::vector<Crossing> c = d.crossings(a, b);
  Index current = d.region(a);
  double t = 0.0;
  for (const Crossing& x : c) {
    ASSERT_EQ(x.before, current);
    ASSERT_GE(x.t, t);
    if (x.t - t > 1e-9) {
      ASSERT_EQ(d.region(a + 0.5 * (t + x.t) * (b - a)), current);
    }
    current = x.after;
    t = x.t;
  }
  ASSERT_EQ(current, d.region(b));
}

TEST(AnalyticDomain, PointsOnInterfacesGetTheHigherPriorityRegion) {
  const auto primitives = make_builtin_domain("primitives");
  // On the box face x = 0 and the cylinder side x^2 + y^2 = 1/4, inside the ball.
  EXPECT_EQ(primitives->region(Vec3(0, 0.5, 0.3)), 7);
  EXPECT_EQ(primitives->region(Vec3(1e-9, 0.5 + 1e-9, 0.3)), 3);   // ball and box only
  EXPECT_EQ(primitives->region(Vec3(-1e-9, 0.5 - 1e-9, 0.3)), 5);  // ball and cylinder
  EXPECT_EQ(primitives->region(Vec3(1, 0, 0)), 3);                  // ball surface in the box
  EXPECT_EQ(primitives->region(Vec3(-1, 0, 0)), 1);                 // ball surface outside
  EXPECT_EQ(primitives->region(Vec3(0, 0, 1.4)), 4);                // cylinder cap centre
  EXPECT_EQ(primitives->region(Vec3(0, 0, 1.2)), 6);                // box top in the cylinder

  const auto shell = make_builtin_domain("thick-sphere");
  EXPECT_EQ(shell->region(Vec3(0.5, 0, 0)), 1);  // the shell wins over the hole
  EXPECT_EQ(shell->region(Vec3(0, 0, -1)), 1);   // and over the outside
  EXPECT_EQ(shell->region(Vec3(0, 0.25, 0)), 0);

  // An inclusion (label 2) wins over its matrix (label 1) on their interface.
  const AnalyticDomain inclusion = layered_domain(
      {{box(Vec3::Constant(-2), Vec3::Constant(2)), 1}, {box(-Vec3::Ones(), Vec3::Ones()), 2}});
  EXPECT_EQ(inclusion.region(Vec3(1, 0.5, 0)), 2);
  EXPECT_EQ(inclusion.region(Vec3(2, 0.5, 0)), 1);
}

TEST(AnalyticDomain, CoincidentSurfacesAreCrossedTogether) {
  // A notch cut flush with the top face: over the notch the top face borders nothing.
  const AnalyticDomain notched = solid_domain(Solid(box(Vec3::Zero(), Vec3::Ones())) -
                                              box(Vec3(0.4, 0.4, 0.8), Vec3(0.6, 0.6, 1.0)));
  EXPECT_EQ(notched.region(Vec3(0.5, 0.5, 1.0)), 0);
  EXPECT_EQ(notched.region(Vec3(0.5, 0.5, 0.8)), 1);  // the notch's floor
  EXPECT_EQ(notched.region(Vec3(0.3, 0.5, 1.0)), 1);
  const Vec3 a(-0.5, 0.5, 1.0), b(1.5, 0.5, 1.0);  // along the top face, over the notch
  const auto c = notched.crossings(a, b);
  ASSERT_EQ(c.size(), 4u);
  const double x[] = {0.0, 0.4, 0.6, 1.0};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(c[k].point.x(), x[k], 1e-15);
    EXPECT_EQ(c[k].after, 1 - k % 2);
  }
  expect_consistent(notched, a, b);
}

TEST(AnalyticDomain, EndPointOnTheSurfaceGivesACrossingAtTheEndOnlyWhenRegionsDiffer) {
  const auto ball = make_builtin_domain("ball");
  auto c = ball->crossings(Vec3(1, 0, 0), Vec3(2, 0, 0));  // from the surface outwards
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].t, 0.0);
  EXPECT_EQ(c[0].before, 1);
  EXPECT_EQ(c[0].after, 0);
  EXPECT_LT((c[0].normal - Vec3::UnitX()).norm(), 1e-15);
  EXPECT_TRUE(ball->crossings(Vec3(1, 0, 0), Vec3(0.2, 0.1, 0)).empty());  // inwards
  c = ball->crossings(Vec3(0, 0, 3), Vec3(0, 0, 1));  // ends on the surface, from outside
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].t, 1.0);
  EXPECT_EQ(c[0].point, Vec3(0, 0, 1));
  EXPECT_EQ(c[0].before, 0);
  EXPECT_EQ(c[0].after, 1);
  EXPECT_LT((c[0].normal + Vec3::UnitZ()).norm(), 1e-15);  // into the ball
  c = ball->crossings(Vec3(-2, 0, 0), Vec3(1, 0, 0));  // through, ending on the far side
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].t, 1.0 / 3.0, 1e-15);
}

TEST(AnalyticDomain, SegmentRunningInAFaceHasTheRegionOfHigherPriority) {
  const auto unit_box = make_builtin_domain("box");
  const Vec3 a(0, 0.5, -0.5), b(0, 0.5, 1.5);  // in the plane of the face x = 0
  const auto c = unit_box->crossings(a, b);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].t, 0.25);
  EXPECT_EQ(c[0].after, 1);
  EXPECT_EQ(c[1].t, 0.75);
  EXPECT_EQ(c[1].after, 0);
  expect_consistent(*unit_box, a, b);
  // Along the interface of two regions.
  const AnalyticDomain two = multi_material_domain(
      {box(Vec3::Zero(), Vec3::Ones()), box(Vec3(1, 0, 0), Vec3(2, 1, 1))});
  EXPECT_EQ(two.region(Vec3(1, 0.5, 0.5)), 2);
  const auto d = two.crossings(Vec3(1, 0.5, -1), Vec3(1, 0.5, 2));
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].after, 2);
  expect_consistent(two, Vec3(1, 0.5, -1), Vec3(1, 0.5, 2));
  expect_consistent(two, Vec3(-1, 0.5, 0.5), Vec3(3, 0.5, 0.5));  // across it
}

TEST(AnalyticDomain, TangentialTouchIsReportedWithEqualRegions) {
  const auto ball = make_builtin_domain("ball");
  // Touches the unit sphere at (0, 1, 0); the discriminant is exactly zero here.
  const auto c = ball->crossings(Vec3(-2, 1, 0), Vec3(2, 1, 0));
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].t, 0.5);
  EXPECT_EQ(c[0].before, 0);
  EXPECT_EQ(c[0].after, 0);
  EXPECT_EQ(ball->region(c[0].point), 1);
  EXPECT_LT((c[0].normal - Vec3::UnitY()).norm(), 1e-15);  // out of the touching point's region
  // A box corner is touched the same way.
  const auto unit_box = make_builtin_domain("box");
  const auto k = unit_box->crossings(Vec3(-1, 1, 1), Vec3(1, -1, 1));
  ASSERT_EQ(k.size(), 1u);
  EXPECT_EQ(k[0].t, 0.5);
  EXPECT_EQ(k[0].before, k[0].after);
}

TEST(AnalyticDomain, CrossingsChainTheRegionsOfRandomSegments) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  for (const std::string name : {"primitives", "cube-inclusion", "thick-sphere"}) {
    SCOPED_TRACE(name);
    const auto d = make_builtin_domain(name);
    const Vec3 centre = d->bounds().centre(), half = 0.5 * d->bounds().size();
    for (int s = 0; s < 300; ++s) {
      const Vec3 a = centre + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(half);
      // Long segments, and short ones like octree edges.
      const Vec3 step = Vec3(u(rng), u(rng), u(rng)).cwiseProduct(half);
      const Vec3 b = s % 2 ? Vec3(centre + step) : Vec3(a + 0.05 * step);
      expect_consistent(*d, a, b);
      // The normal points from before into after.
      for (const Crossing& x : d->crossings(a, b)) {
        if (x.before == x.after) continue;
        EXPECT_EQ(d->region(x.point - 1e-9 * x.normal), x.before);
        EXPECT_EQ(d->region(x.point + 1e-9 * x.normal), x.after);
      }
    }
    // Axis-aligned segments through the points where interfaces meet the grid exactly.
    for (double y : {-0.5, 0.0, 0.5})
      for (double z : {-0.6, 0.0, 1.2, 1.4}) expect_consistent(*d, Vec3(-2, y, z), Vec3(2, y, z));
  }
}

TEST(AnalyticDomain, MultiMaterialCrossingsHaveBothRegionsAndNormalsIntoTheNextOne) {
  const auto d = make_builtin_domain("primitives");
  // Along x at y = 0.2, z = 0.1: ball (1) -> ball+cylinder (5) -> all (7) -> ball+box (3)
  // -> box (2) -> outside.
  const auto c = d->crossings(Vec3(-2, 0.2, 0.1), Vec3(2, 0.2, 0.1));
  const Index expected[][2] = {{0, 1}, {1, 5}, {5, 7}, {7, 3}, {3, 2}, {2, 0}};
  ASSERT_EQ(c.size(), 6u);
  const double rho = std::sqrt(0.25 - 0.04), ball = std::sqrt(1 - 0.04 - 0.01);
  const double x[] = {-ball, -rho, 0.0, rho, ball, 1.2};
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(c[k].before, expected[k][0]);
    EXPECT_EQ(c[k].after, expected[k][1]);
    EXPECT_NEAR(c[k].point.x(), x[k], 1e-14);
    EXPECT_GT(c[k].normal.x(), 0.0) << k;  // travelling along +x from before into after
  }
}

TEST(AnalyticDomain, BatchQueriesEqualSingleQueriesAndRepeat) {
  const auto d = make_builtin_domain("primitives");
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::vector<Vec3> points(20000), a(2000), b(2000);
  for (Vec3& p : points) p = Vec3(u(rng), u(rng), u(rng));
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = points[i], b[i] = points[i + 7000];
  std::vector<Index> regions(points.size()), again(points.size());
  d->region(points, regions);
  d->region(points, again);
  EXPECT_EQ(regions, again);
  for (std::size_t i = 0; i < points.size(); ++i) ASSERT_EQ(regions[i], d->region(points[i]));

  std::vector<std::vector<Crossing>> batch, batch_again;
  d->crossings(a, b, batch);
  d->crossings(a, b, batch_again);
  ASSERT_EQ(batch.size(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto single = d->crossings(a[i], b[i]);
    ASSERT_EQ(batch[i].size(), single.size());
    for (std::size_t k = 0; k < single.size(); ++k) {
      EXPECT_EQ(batch[i][k].t, single[k].t);  // bitwise: the same computation
      EXPECT_EQ(batch[i][k].normal, single[k].normal);
      EXPECT_EQ(batch[i][k].before, single[k].before);
      EXPECT_EQ(batch[i][k].after, single[k].after);
      EXPECT_EQ(batch_again[i][k].t, single[k].t);
    }
  }
  EXPECT_THROW(d->region(points, std::span<Index>(regions).first(3)), std::invalid_argument);
}

TEST(AnalyticDomain, NormalsPointOutOfTheHigherPriorityRegionAndSurfacesAreNamed) {
  const auto shell = make_builtin_domain("thick-sphere");
  const auto& named = dynamic_cast<const AnalyticDomain&>(*shell);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g;
  for (int s = 0; s < 100; ++s) {
    const Vec3 dir = Vec3(g(rng), g(rng), g(rng)).normalized();
    // Near the outer surface: outward; near the inner one: towards the centre.
    EXPECT_LT((shell->normal(0.98 * dir) - dir).norm(), 1e-14);
    EXPECT_LT((shell->normal(1.01 * dir) - dir).norm(), 1e-14);
    EXPECT_LT((shell->normal(0.52 * dir) + dir).norm(), 1e-14);
    EXPECT_LT((shell->normal(0.49 * dir) + dir).norm(), 1e-14);
    EXPECT_EQ(named.surface_name(0.99 * dir), "outer");
    EXPECT_EQ(named.surface_name(0.51 * dir), "inner");
  }
  // In the multi-material scene the normal points out of the region of higher label.
  const auto d = make_builtin_domain("primitives");
  EXPECT_LT((d->normal(Vec3(0.01, 0.2, 0.1)) + Vec3::UnitX()).norm(), 1e-15);  // 7 vs 5
  EXPECT_LT((d->normal(Vec3(1.19, 0.2, 0.1)) - Vec3::UnitX()).norm(), 1e-15);  // 2 vs 0
}

TEST(AnalyticDomain, BoundsAndRegions) {
  const auto ball = make_builtin_domain("ball");
  EXPECT_EQ(ball->bounds().lo, Vec3::Constant(-1));
  EXPECT_EQ(ball->bounds().hi, Vec3::Constant(1));
  EXPECT_EQ(ball->regions(), std::vector<Index>{1});
  const auto d = make_builtin_domain("primitives");
  EXPECT_EQ(d->bounds().lo, Vec3(-1, -1.2, -1.4));
  EXPECT_EQ(d->bounds().hi, Vec3(1.2, 1.2, 1.4));
  EXPECT_EQ(d->regions(), (std::vector<Index>{1, 2, 3, 4, 5, 6, 7}));
  // A cylinder inside a ball: the overlap {cylinder only} (label 2) does not occur.
  const AnalyticDomain nested = multi_material_domain(
      {sphere(Vec3::Zero(), 1.0), cylinder(Vec3(0, 0, -0.5), Vec3(0, 0, 0.5), 0.3)});
  EXPECT_EQ(nested.regions(), (std::vector<Index>{1, 3}));
  // A rotated box: the bounds are its corners'.
  const AnalyticDomain tilted = solid_domain(moved(
      box(-Vec3::Ones(), Vec3::Ones()), Rigid{euler_zxz(std::numbers::pi / 4, 0, 0), Vec3::Zero()}));
  EXPECT_NEAR(tilted.bounds().hi.x(), std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(tilted.bounds().hi.z(), 1.0, 1e-15);
}

TEST(AnalyticDomain, InvalidInputIsAnInputError) {
  EXPECT_THROW(solid_domain(sphere(Vec3::Zero(), -1.0)), InputError);
  EXPECT_THROW(solid_domain(box(Vec3::Ones(), Vec3::Zero())), InputError);
  EXPECT_THROW(solid_domain(torus(Vec3::Zero(), Vec3::UnitZ(), 0.2, 0.3)), InputError);
  EXPECT_THROW(solid_domain(half_space(Vec3::Zero(), Vec3::UnitZ())), InputError);  // unbounded
  EXPECT_NO_THROW(solid_domain(Solid(sphere(Vec3::Zero(), 1)) & half_space(Vec3::Zero(), Vec3::UnitZ())));
  EXPECT_THROW(multi_material_domain(std::vector<Primitive>(17, sphere(Vec3::Zero(), 1))),
               InputError);
  EXPECT_THROW(AnalyticDomain({sphere(Vec3::Zero(), 1)}, {1, 1}), InputError);  // outside labelled
  Primitive skewed = sphere(Vec3::Zero(), 1);
  skewed.frame.rotation(0, 1) = 0.5;
  EXPECT_THROW(solid_domain(skewed), InputError);
  try {
    solid_domain(cylinder(Vec3::Zero(), Vec3::UnitZ(), 0.0, "pipe"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'pipe' (cylinder): radius"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace volmesh
