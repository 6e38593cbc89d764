// Surface domains on boxes, where every answer is known exactly: regions on, near and away
// from the surface, nesting and labels, crossings against the box's own slab clipping,
// pseudo-normals, and the surfaces that must be refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "test_surface_domain_support.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/surface.hpp"

namespace volmesh {
namespace {

using surface_test::box_surface;

SurfaceDomain unit_cube(int n = 4) {
  return SurfaceDomain({{box_surface(Vec3::Zero(), Vec3::Ones(), n)}});
}

TEST(SurfaceDomain, RegionsInsideOutsideAndWithin1e12OfAFace) {
  const SurfaceDomain d = unit_cube();
  EXPECT_EQ(d.region({0.5, 0.5, 0.5}), 1);
  EXPECT_EQ(d.region({0.3, 0.9, 0.1}), 1);
  EXPECT_EQ(d.region({1.5, 0.5, 0.5}), 0);
  EXPECT_EQ(d.region({-3, 7, 2}), 0);
  for (double x : {0.1, 0.37, 0.5, 0.75}) {  // 0.5 and 0.75 lie on triangulation lines
    EXPECT_EQ(d.region({1.0 - 1e-12, x, 0.3}), 1);
    EXPECT_EQ(d.region({1.0 + 1e-12, x, 0.3}), 0);
    EXPECT_EQ(d.region({x, 0.6, 1e-12}), 1);
    EXPECT_EQ(d.region({x, 0.6, -1e-12}), 0);
    EXPECT_EQ(d.region({x, 1e-300, 0.6}), 1);
    EXPECT_EQ(d.region({x, -1e-300, 0.6}), 0);
  }
  EXPECT_EQ(d.regions(), std::vector<Index>{1});
  EXPECT_EQ(d.bounds().lo, Vec3::Zero());
  EXPECT_EQ(d.bounds().hi, Vec3::Ones());
}

// Points on a face, on a triangulation edge, on a mesh vertex, on a cube edge and on a cube
// corner: inside, whatever the order of the queries, and the crossings of segments ending
// there agree with the region of the end point.
TEST(SurfaceDomain, PointsOnTheSurfaceAreInsideFromEveryQuery) {
  const SurfaceDomain d = unit_cube();
  const std::vector<Vec3> on{{0.3, 0.6, 1.0}, {0.3, 0.6, 0.0},  {1.0, 0.1, 0.2},    {0.25, 0.25, 0},
                             {0.5, 0.5, 0.0}, {0.5, 0.75, 1.0}, {1.0, 1.0, 0.4},    {0.0, 0.3, 1.0},
                             {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0},  {0.125, 0.125, 1.0}};
  for (const Vec3& p : on) EXPECT_EQ(d.region(p), 1) << p.transpose();
  std::vector<Vec3> shuffled = on;
  std::mt19937 rng(7);
  for (int round = 0; round < 3; ++round) {
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    std::vector<Index> regions(shuffled.size());
    d.region(shuffled, regions);
    EXPECT_TRUE(std::all_of(regions.begin(), regions.end(), [](Index r) { return r == 1; }));
  }
  const Vec3 centre(0.5, 0.5, 0.5);
  for (const Vec3& p : on) {
    const Vec3 outside = p + 0.5 * (p - centre);
    // Outside -> on: one crossing, at t = 1, into region 1.
    const auto in = d.crossings(outside, p);
    ASSERT_EQ(in.size(), 1u) << p.transpose();
    EXPECT_EQ(in[0].t, 1.0);
    EXPECT_EQ(in[0].point, p);
    EXPECT_EQ(in[0].before, 0);
    EXPECT_EQ(in[0].after, 1);
    EXPECT_LT(in[0].normal.dot(p - centre), 0.0);  // from outside into the cube
    // On -> outside: at t = 0, out of region 1.
    const auto out = d.crossings(p, outside);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].t, 0.0);
    EXPECT_EQ(out[0].before, 1);
    EXPECT_EQ(out[0].after, 0);
    EXPECT_GT(out[0].normal.dot(p - centre), 0.0);
    // Inside -> on: the region does not change.
    EXPECT_TRUE(d.crossings(centre, p).empty()) << p.transpose();
  }
}

// Entry and exit of a segment through [0, 1]^3 by slab clipping.
struct Clipped {
  double t0, t1;
  int axis0, axis1;
};
std::optional<Clipped> clip_unit_box(const Vec3& a, const Vec3& b) {
  Clipped c{-1e300, 1e300, -1, -1};
  for (int k = 0; k < 3; ++k) {
    const double d = b[k] - a[k];
    double lo = (0.0 - a[k]) / d, hi = (1.0 - a[k]) / d;
    if (lo > hi) std::swap(lo, hi);
    if (lo > c.t0) c = {lo, c.t1, k, c.axis1};
    if (hi < c.t1) c = {c.t0, hi, c.axis0, k};
  }
  if (c.t0 >= c.t1) return std::nullopt;
  return c;
}

TEST(SurfaceDomain, CrossingsOfRandomSegmentsMatchTheBoxExactly) {
  const SurfaceDomain d = unit_cube();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.6, 1.6);
  int crossed = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const auto clip = clip_unit_box(a, b);
    std::vector<Crossing> expected;
    if (clip && clip->t0 > 0.0 && clip->t0 < 1.0) {
      Vec3 n = Vec3::Zero();
      n[clip->axis0] = b[clip->axis0] > a[clip->axis0] ? 1.0 : -1.0;  // into the box
      expected.push_back({clip->t0, a + clip->t0 * (b - a), 0, 1, n});
    }
    if (clip && clip->t1 > 0.0 && clip->t1 < 1.0) {
      Vec3 n = Vec3::Zero();
      n[clip->axis1] = b[clip->axis1] > a[clip->axis1] ? 1.0 : -1.0;  // out of it
      expected.push_back({clip->t1, a + clip->t1 * (b - a), 1, 0, n});
    }
    const auto got = d.crossings(a, b);
    ASSERT_EQ(got.size(), expected.size()) << a.transpose() << " -> " << b.transpose();
    crossed += !got.empty();
    for (std::size_t k = 0; k < got.size(); ++k) {
      EXPECT_NEAR(got[k].t, expected[k].t, 1e-12);
      EXPECT_LT((got[k].point - expected[k].point).norm(), 1e-12);
      EXPECT_EQ(got[k].before, expected[k].before);
      EXPECT_EQ(got[k].after, expected[k].after);
      EXPECT_LT((got[k].normal - expected[k].normal).norm(), 1e-12);
    }
    EXPECT_EQ(d.region(a), clip && clip->t0 <= 0.0 && clip->t1 >= 0.0 ? 1 : 0);
  }
  EXPECT_GT(crossed, 1000);
}

// Through a cube edge, a cube corner, a triangulation edge and a mesh vertex: one crossing
// each way, with the edge's or vertex's pseudo-normal; grazing an edge or a corner from
// outside is a touch, 0 -> 0, its normal pointing out of the cube.
TEST(SurfaceDomain, CrossingsThroughEdgesAndVerticesCountOnce) {
  const SurfaceDomain d = unit_cube();
  const auto one_each_way = [&](const Vec3& a, const Vec3& b, const Vec3& normal_in) {
    const auto c = d.crossings(a, b);
    ASSERT_EQ(c.size(), 2u) << a.transpose() << " -> " << b.transpose();
    EXPECT_EQ(c[0].before, 0);
    EXPECT_EQ(c[0].after, 1);
    EXPECT_EQ(c[1].before, 1);
    EXPECT_EQ(c[1].after, 0);
    EXPECT_LT((c[0].normal - normal_in).norm(), 1e-12) << c[0].normal.transpose();
  };
  const double r = 1.0 / std::sqrt(2.0), s = 1.0 / std::sqrt(3.0);
  one_each_way({1.5, 1.5, 0.3}, {-0.5, -0.5, 0.3}, {-r, -r, 0});    // cube edge, diagonal
  one_each_way({1.5, 1.5, 1.5}, {-0.5, -0.5, -0.5}, {-s, -s, -s});  // corners
  one_each_way({0.5, 0.25, 2.0}, {0.5, 0.25, -1.0}, {0, 0, -1});    // triangulation edge
  one_each_way({0.25, 0.5, 2.0}, {0.25, 0.5, -1.0}, {0, 0, -1});    // mesh vertex
  one_each_way({0.3, 0.7, 1.3}, {0.7, 0.3, -0.3}, {0, 0, -1});      // diagonal edge

  const auto touch = [&](const Vec3& a, const Vec3& b, const Vec3& normal) {
    const auto c = d.crossings(a, b);
    ASSERT_EQ(c.size(), 1u) << a.transpose() << " -> " << b.transpose();
    EXPECT_EQ(c[0].before, 0);
    EXPECT_EQ(c[0].after, 0);
    EXPECT_NEAR(c[0].t, 0.5, 1e-15);
    EXPECT_LT((c[0].normal - normal).norm(), 1e-12) << c[0].normal.transpose();
  };
  touch({2.0, 0.0, 0.4}, {0.0, 2.0, 0.4}, {r, r, 0});  // grazes the edge x = y = 1
  touch({1.5, 1.0, 0.5}, {0.5, 1.0, 1.5}, {s, s, s});  // in the face's plane, by the corner
}

TEST(SurfaceDomain, SegmentsRunningInAFaceAreInside) {
  const SurfaceDomain d = unit_cube();
  // In the plane z = 1 from outside across the face and out again.
  const auto c = d.crossings({-0.5, 0.3, 1.0}, {1.5, 0.6, 1.0});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].t, 0.25, 1e-15);
  EXPECT_EQ(c[0].before, 0);
  EXPECT_EQ(c[0].after, 1);
  EXPECT_NEAR(c[1].t, 0.75, 1e-15);
  EXPECT_EQ(c[1].before, 1);
  EXPECT_EQ(c[1].after, 0);
  // Within the face: no change at all.
  EXPECT_TRUE(d.crossings({0.1, 0.2, 1.0}, {0.9, 0.7, 1.0}).empty());
}

TEST(SurfaceDomain, NestedSurfacesMakeNestedRegions) {
  const TriSurface outer = box_surface(Vec3::Constant(-2), Vec3::Constant(2), 2);
  const TriSurface inner = box_surface(Vec3::Constant(-1), Vec3::Constant(1), 3);
  for (bool inner_first : {false, true}) {
    std::vector<LabelledSurface> list{{outer, 0, "outer"}, {inner, 0, "inner"}};
    if (inner_first) std::swap(list[0], list[1]);
    const SurfaceDomain d(std::move(list));
    EXPECT_EQ(d.region(Vec3::Zero()), 2);
    EXPECT_EQ(d.region({1.5, 0.2, 0.1}), 1);
    EXPECT_EQ(d.region({0.2, -1.7, 1.9}), 1);
    EXPECT_EQ(d.region({3.0, 0.0, 0.0}), 0);
    EXPECT_EQ(d.region({1.0, 0.3, 0.2}), 2);  // on the inner surface: the inner region
    EXPECT_EQ(d.region({2.0, 0.3, 0.2}), 1);
    EXPECT_EQ(d.regions(), (std::vector<Index>{1, 2}));
    EXPECT_EQ(d.bounds().lo, Vec3::Constant(-2));
    EXPECT_EQ(d.depths(), inner_first ? (std::vector<Index>{1, 0}) : (std::vector<Index>{0, 1}));

    const Vec3 a(-3, 0.1, 0.2), b(3, 0.1, 0.2);
    const auto c = d.crossings(a, b);
    ASSERT_EQ(c.size(), 4u);
    const std::array<double, 4> x{-2, -1, 1, 2};
    const std::array<std::pair<Index, Index>, 4> change{{{0, 1}, {1, 2}, {2, 1}, {1, 0}}};
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR(c[k].t, (x[k] + 3) / 6, 1e-15);
      EXPECT_EQ(c[k].before, change[k].first);
      EXPECT_EQ(c[k].after, change[k].second);
      EXPECT_EQ(c[k].normal, Vec3::UnitX());  // from before into after: along +x each time
    }
    EXPECT_EQ(d.normal({0.9, 0.1, 0.0}), Vec3::UnitX());    // the inner surface, outward
    EXPECT_EQ(d.normal({1.9, 0.1, 0.0}), Vec3::UnitX());    // the outer one
    EXPECT_EQ(d.normal({-1.4, 0.1, 0.0}), -Vec3::UnitX());  // nearer the inner: out of it
  }
  const SurfaceDomain labelled({{outer, 7, "outer"}, {inner, 3, "inner"}});
  EXPECT_EQ(labelled.region(Vec3::Zero()), 3);
  EXPECT_EQ(labelled.region({1.5, 0, 0}), 7);
  EXPECT_EQ(labelled.regions(), (std::vector<Index>{3, 7}));
  EXPECT_EQ(labelled.labels(), (std::vector<Index>{7, 3}));
}

TEST(SurfaceDomain, PseudoNormalsOfFacesEdgesAndCorners) {
  const SurfaceDomain d = unit_cube(3);
  const double r = 1.0 / std::sqrt(2.0), s = 1.0 / std::sqrt(3.0);
  EXPECT_LT((d.normal({0.5, 0.4, 1.2}) - Vec3::UnitZ()).norm(), 1e-15);
  EXPECT_LT((d.normal({0.5, 0.4, 0.9}) - Vec3::UnitZ()).norm(), 1e-15);  // from inside
  EXPECT_LT((d.normal({1.3, 1.2, 0.4}) - Vec3(r, r, 0)).norm(), 1e-15);
  EXPECT_LT((d.normal({-0.3, -0.2, -0.4}) - Vec3(-s, -s, -s)).norm(), 1e-15);
  EXPECT_LT((d.normal({1.0, 1.0, 1.0}) - Vec3(s, s, s)).norm(), 1e-15);
}

// Two overlapping boxes given as one surface, as a careless scan might be: the overlap
// (winding number 2) is inside, not outside as parity would have it.
TEST(SurfaceDomain, SelfOverlappingSurfaceIsInsideWhereTheWindingNumberIsPositive) {
  TriSurface s = box_surface(Vec3::Zero(), Vec3::Ones(), 2);
  const TriSurface t = box_surface(Vec3::Constant(0.5), Vec3::Constant(1.5), 2);
  const Index offset = s.num_points();
  s.points.insert(s.points.end(), t.points.begin(), t.points.end());
  for (auto tri : t.triangles)
    s.triangles.push_back({tri[0] + offset, tri[1] + offset, tri[2] + offset});
  const SurfaceDomain d({{s}});
  EXPECT_EQ(d.region({0.2, 0.2, 0.2}), 1);
  EXPECT_EQ(d.region({0.75, 0.8, 0.7}), 1);
  EXPECT_EQ(d.region({1.3, 1.3, 1.3}), 1);
  EXPECT_EQ(d.region({1.3, 0.2, 0.2}), 0);
  // Through both boxes: in at x = 0, and out only at x = 1.5.
  const auto c = d.crossings({-0.5, 0.7, 0.6}, {2.0, 0.7, 0.6});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].t, 0.2, 1e-15);
  EXPECT_NEAR(c[1].t, 0.8, 1e-15);
}

void expect_refused(TriSurface s, const std::string& what) {
  try {
    SurfaceDomain d({{std::move(s), 0, "part.stl"}});
    FAIL() << "accepted a surface with " << what;
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("part.stl: ", 0), 0u) << m;
    EXPECT_NE(m.find(what), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

TEST(SurfaceDomain, RefusesSurfacesThatBoundNothing) {
  TriSurface hole = box_surface(Vec3::Zero(), Vec3::Ones(), 2);
  hole.triangles.erase(hole.triangles.begin() + 5);
  expect_refused(hole, "hole");

  TriSurface flipped_one = box_surface(Vec3::Zero(), Vec3::Ones(), 2);
  std::swap(flipped_one.triangles[3][0], flipped_one.triangles[3][1]);
  expect_refused(flipped_one, "orientation inconsistent");

  TriSurface fin = box_surface(Vec3::Zero(), Vec3::Ones(), 1);  // a third triangle on an edge
  fin.points.push_back({0.5, 0.5, 2.0});
  fin.triangles.push_back({fin.triangles[0][0], fin.triangles[0][1], fin.num_points() - 1});
  expect_refused(fin, "non-manifold");

  TriSurface flat = box_surface(Vec3::Zero(), Vec3::Ones(), 1);
  flat.points.push_back({0.5, 0.5, 0.5});
  flat.triangles.push_back({0, 1, 1});
  expect_refused(flat, "collinear");

  expect_refused(TriSurface{}, "no triangles");
  EXPECT_THROW(SurfaceDomain(std::vector<LabelledSurface>{}), InputError);
  std::vector<LabelledSurface> negative{{box_surface(Vec3::Zero(), Vec3::Ones(), 1), -2}};
  EXPECT_THROW(SurfaceDomain(std::move(negative)), InputError);
}

TEST(SurfaceDomain, InwardSurfaceIsFlipped) {
  TriSurface s = box_surface(Vec3::Zero(), Vec3::Ones(), 2);
  for (auto& t : s.triangles) std::swap(t[1], t[2]);
  const SurfaceDomain d({{s}});
  EXPECT_EQ(d.region(Vec3::Constant(0.5)), 1);
  EXPECT_EQ(d.region(Vec3::Constant(1.5)), 0);
  EXPECT_LT((d.normal({0.5, 0.5, 1.1}) - Vec3::UnitZ()).norm(), 1e-15);
}

}  // namespace
}  // namespace volmesh
