// Layered domains on planar and piecewise-planar sheets, where every answer is known:
// regions, crossings and normals against the planes themselves, priorities on interfaces,
// a pinch-out, a fault, and the sheets that must be refused.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "volmesh/core/errors.hpp"
#include "volmesh/domain/layered.hpp"
#include "volmesh/domain/prioritized.hpp"

namespace volmesh {
namespace {

const Box3 kBox{Vec3(0, 0, 0), Vec3(2, 1, 1)};

Sheet flat(double z, const std::string& name, const Box3& box = kBox) {
  return plane_sheet(box, 2, Vec3(0, 0, z), Vec3::UnitZ(), name);
}

// z = 0.3, the plane z = 0.5 + 0.1 x + 0.05 y, z = 0.8: labels 1 to 4 from the bottom.
struct Plane {
  Vec3 point, normal;  // normal: unit, upward
  double height(double x, double y) const {
    return point.z() - (normal.x() * (x - point.x()) + normal.y() * (y - point.y())) / normal.z();
  }
};
const std::vector<Plane> kPlanes{{Vec3(0, 0, 0.3), Vec3::UnitZ()},
                                 {Vec3(0, 0, 0.5), Vec3(-0.1, -0.05, 1).normalized()},
                                 {Vec3(0, 0, 0.8), Vec3::UnitZ()}};

LayeredDomain three_planes() {
  LayeredModel m;
  m.box = kBox;
  LayerBlock b;
  const char* names[] = {"p0", "p1", "p2"};
  for (std::size_t i = 0; i < kPlanes.size(); ++i)
    b.horizons.push_back(plane_sheet(kBox, 2, kPlanes[i].point, kPlanes[i].normal, names[i]));
  b.labels = {1, 2, 3, 4};
  m.blocks.push_back(b);
  return LayeredDomain(m);
}

bool in_box(const Vec3& p) {
  return (p.array() >= kBox.lo.array()).all() && (p.array() <= kBox.hi.array()).all();
}

Index expected_region(const Vec3& p) {
  if (!in_box(p)) return 0;
  Index below = 0;
  for (const Plane& q : kPlanes) below += p.z() >= q.height(p.x(), p.y());
  return below + 1;
}

TEST(LayeredDomain, RegionsOfThreePlanesAgreeWithTheirHeights) {
  const LayeredDomain d = three_planes();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p(2 * u(rng), u(rng), u(rng));
    // Far from the tilted plane's rounding (its corners are computed in double).
    if (std::abs(p.z() - kPlanes[1].height(p.x(), p.y())) < 1e-12) continue;
    ASSERT_EQ(d.region(p), expected_region(p)) << p.transpose();
  }
  EXPECT_EQ(d.regions(), (std::vector<Index>{1, 2, 3, 4}));
  const Vec3 nan(std::nan(""), 0.5, 0.5);
  EXPECT_EQ(d.region(nan), 0);
  EXPECT_TRUE(d.normal(nan).allFinite());
  EXPECT_TRUE(d.crossings(nan, Vec3(1, 0.5, 0.5)).empty());
  EXPECT_EQ(d.bounds().lo, kBox.lo);
  EXPECT_EQ(d.bounds().hi, kBox.hi);
}

TEST(LayeredDomain, PointsOnAnInterfaceGetTheHigherLabelOrThePriorityGiven) {
  const LayeredDomain d = three_planes();
  for (double x : {0.0, 0.25, 1.0, 1.7, 2.0})
    for (double y : {0.0, 0.5, 0.9}) {
      EXPECT_EQ(d.region({x, y, 0.3}), 2);
      EXPECT_EQ(d.region({x, y, std::nextafter(0.3, 0.0)}), 1);
      EXPECT_EQ(d.region({x, y, std::nextafter(0.3, 1.0)}), 2);
      EXPECT_EQ(d.region({x, y, 0.8}), 4);
      EXPECT_EQ(d.region({x, y, 1.0}), 4);  // the box's faces belong to it
      EXPECT_EQ(d.region({x, y, 0.0}), 1);
      EXPECT_EQ(d.region({x, y, std::nextafter(1.0, 2.0)}), 0);
    }
  EXPECT_EQ(d.region({0, 0, 0.5}), 3);  // a corner of the tilted plane
  EXPECT_EQ(d.region({0, 0, std::nextafter(0.5, 0.0)}), 2);

  // 1 above 2 above 4 above 3: on the 1-2 interface 1 wins, on 3-4 4 wins.
  LayeredModel m;
  m.box = kBox;
  m.blocks.push_back({{flat(0.3, "a"), flat(0.5, "b"), flat(0.8, "c")}, {4, 3, 2, 1}});
  const auto ranked = prioritized(std::make_unique<LayeredDomain>(m), {1, 2, 4, 3});
  // Labels bottom to top are ranks 4 3 2 1, i.e. the labels 1 2 4 3.
  EXPECT_EQ(ranked->region({1, 0.5, 0.1}), 1);
  EXPECT_EQ(ranked->region({1, 0.5, 0.3}), 1);
  EXPECT_EQ(ranked->region({1, 0.5, 0.4}), 2);
  EXPECT_EQ(ranked->region({1, 0.5, 0.5}), 2);
  EXPECT_EQ(ranked->region({1, 0.5, 0.8}), 4);
  EXPECT_EQ(ranked->region({1, 0.5, 0.9}), 3);
  EXPECT_EQ(ranked->regions(), (std::vector<Index>{1, 2, 3, 4}));
  const std::vector<Crossing> c = ranked->crossings({1, 0.5, -1}, {1, 0.5, 2});
  ASSERT_EQ(c.size(), 5u);
  EXPECT_EQ(c[1].before, 1);
  EXPECT_EQ(c[1].after, 2);
  EXPECT_EQ(c[3].after, 3);
}

// The crossings of a segment with the planes and the box, computed from the planes.
struct Expected {
  double t;
  Vec3 normal;
};
std::vector<Expected> analytic_crossings(const Vec3& a, const Vec3& b) {
  std::vector<std::pair<double, Vec3>> cuts;  // t, upward or outward normal
  for (const Plane& q : kPlanes) {
    const double fa = q.normal.dot(a - q.point), fb = q.normal.dot(b - q.point);
    if ((fa < 0) != (fb < 0)) cuts.push_back({fa / (fa - fb), q.normal});
  }
  for (int k = 0; k < 3; ++k)
    for (double c : {kBox.lo[k], kBox.hi[k]})
      if ((a[k] < c) != (b[k] < c)) cuts.push_back({(c - a[k]) / (b[k] - a[k]), Vec3::Unit(k)});
  std::sort(cuts.begin(), cuts.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Expected> out;
  for (const auto& [t, n] : cuts) {
    const Vec3 before = a + (t - 1e-9) * (b - a), after = a + (t + 1e-9) * (b - a);
    if (expected_region(before) != expected_region(after))
      out.push_back({t, n.dot(b - a) > 0 ? n : Vec3(-n)});
  }
  return out;
}

// The crossings of [a, b] against the planes' (to 1e-12), the regions in between against
// their heights; returns how many.
std::size_t expect_planes_crossings(const LayeredDomain& d, const Vec3& a, const Vec3& b) {
  const std::vector<Expected> expected = analytic_crossings(a, b);
  const std::vector<Crossing> got = d.crossings(a, b);
  EXPECT_EQ(got.size(), expected.size()) << a.transpose() << " -> " << b.transpose();
  if (got.size() != expected.size()) return 0;
  Index current = d.region(a);
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_NEAR(got[k].t, expected[k].t, 1e-12);
    EXPECT_LT((got[k].normal - expected[k].normal).norm(), 1e-12);
    EXPECT_LT((got[k].point - (a + got[k].t * (b - a))).norm(), 1e-15 * 4);
    EXPECT_EQ(got[k].before, current);
    EXPECT_NE(got[k].after, got[k].before);
    EXPECT_EQ(got[k].after, expected_region(a + (expected[k].t + 1e-9) * (b - a)));
    current = got[k].after;
  }
  EXPECT_EQ(current, d.region(b));
  return got.size();
}

TEST(LayeredDomain, CrossingsOfRandomSegmentsMatchThePlanesTo1e12) {
  const LayeredDomain d = three_planes();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.3, 1.3);
  std::size_t crossings = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 a(2 * u(rng), u(rng), u(rng)), b(2 * u(rng), u(rng), u(rng));
    crossings += expect_planes_crossings(d, a, b);
  }
  EXPECT_GT(crossings, 3000u);
}

// The same planes as graphs on a 65 x 33 grid (8,192 triangles each): short segments find
// their triangles in the sheets' buckets, long ones in the tree; both must miss none, also
// where a segment runs through the triangles' sides and corners.
TEST(LayeredDomain, CrossingsOfFinelyTriangulatedPlanesMatchThePlanesTo1e12) {
  LayeredModel m;
  m.box = kBox;
  LayerBlock b;
  for (std::size_t i = 0; i < kPlanes.size(); ++i)
    b.horizons.push_back(graph_sheet(
        kBox, 2, 65, 33, [i](double x, double y) { return kPlanes[i].height(x, y); }, "p" + std::to_string(i)));
  b.labels = {1, 2, 3, 4};
  m.blocks.push_back(b);
  const LayeredDomain d(m);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0), step(-0.05, 0.05);
  std::size_t crossings = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 a(2 * u(rng), u(rng), u(rng));
    crossings += expect_planes_crossings(d, a, a + Vec3(step(rng), step(rng), 4 * step(rng)));
  }
  for (int i = 0; i < 300; ++i) {
    const Vec3 a(2 * u(rng), u(rng), u(rng)), c(2 * u(rng), u(rng), u(rng));
    crossings += expect_planes_crossings(d, a, c);
  }
  // Vertical segments through grid vertices and along grid lines (x = i / 32, y = j / 32).
  for (int i = 0; i <= 64; i += 3)
    for (int j = 0; j <= 32; j += 3) {
      const double x = i / 32.0, y = j / 32.0;
      EXPECT_EQ(expect_planes_crossings(d, {x, y, 0.05}, {x, y, 0.95}), 3u) << x << " " << y;
      crossings += expect_planes_crossings(d, {x, y + 0.01, 0.45}, {x, y + 0.02, 0.65});
      crossings += expect_planes_crossings(d, {x + 0.01, y, 0.45}, {x + 0.02, y, 0.65});
    }
  EXPECT_GT(crossings, 5000u);
}

TEST(LayeredDomain, CrossingsAtEndPointsOnAnInterface) {
  const LayeredDomain d = three_planes();
  // Starting on z = 0.3 (region 2) and going down: a crossing at t = 0 into region 1.
  std::vector<Crossing> c = d.crossings({1, 0.5, 0.3}, {1, 0.5, 0.1});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].t, 0.0);
  EXPECT_EQ(c[0].before, 2);
  EXPECT_EQ(c[0].after, 1);
  EXPECT_LT((c[0].normal - Vec3(0, 0, -1)).norm(), 1e-15);
  // Going up from there stays in region 2: nothing at t = 0.
  c = d.crossings({1, 0.5, 0.3}, {1, 0.5, 0.4});
  EXPECT_TRUE(c.empty());
  // Ending on it from below: a crossing at t = 1.
  c = d.crossings({1, 0.5, 0.1}, {1, 0.5, 0.3});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].t, 1.0);
  EXPECT_EQ(c[0].after, 2);
  // Running inside the interface, from outside the box: 0 -> 2 at the box face.
  c = d.crossings({-1, 0.5, 0.3}, {1.5, 0.5, 0.3});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].before, 0);
  EXPECT_EQ(c[0].after, 2);
  EXPECT_NEAR(c[0].t, 0.4, 1e-15);
  EXPECT_LT((c[0].normal - Vec3(1, 0, 0)).norm(), 1e-15);
}

TEST(LayeredDomain, NormalsPointOutOfTheHigherLabel) {
  const LayeredDomain d = three_planes();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.1, 0.9);
  for (int i = 0; i < 200; ++i) {
    const double x = 2 * u(rng), y = u(rng);
    for (std::size_t k = 0; k < kPlanes.size(); ++k) {
      const double h = kPlanes[k].height(x, y);
      for (double off : {-1e-3, 1e-3, 0.0})
        EXPECT_LT((d.normal({x, y, h + off}) + kPlanes[k].normal).norm(), 1e-12);
    }
  }
  // Near the box faces: outward.
  EXPECT_LT((d.normal({1.0, 0.5, 0.999}) - Vec3(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((d.normal({1.99, 0.5, 0.4}) - Vec3(1, 0, 0)).norm(), 1e-15);
  EXPECT_LT((d.normal({0.01, 0.5, 0.4}) - Vec3(-1, 0, 0)).norm(), 1e-15);
  EXPECT_EQ(d.surface_name({1.0, 0.5, 0.31}), "p0");
  EXPECT_EQ(d.surface_name({1.0, 0.001, 0.4}), "ymin");
  // Boundary faces are named by the nearest box face, also where a horizon is nearer or
  // meets the face, and beside the box.
  EXPECT_EQ(d.boundary_name({1.0, 0.5, 0.31}), "zmin");
  EXPECT_EQ(d.boundary_name({2.0, 0.5, 0.3}), "xmax");
  EXPECT_EQ(d.boundary_name({1e-12, 0.5, 0.7}), "xmin");
  EXPECT_EQ(d.boundary_name({1.0, -0.01, 0.5}), "ymin");
  EXPECT_EQ(d.boundary_name({2.01, 0.5, 0.9}), "xmax");
}

// Horizon B rests on A (z = 0.375) for x <= 1 and rises to 0.625 at x = 2: the middle
// layer pinches out. (Dyadic heights: the points below are exactly where they seem.)
LayeredDomain pinch_out() {
  LayeredModel m;
  m.box = kBox;
  Sheet b = graph_sheet(
      kBox, 2, 3, 2, [](double x, double) { return x <= 1 ? 0.375 : 0.375 + 0.25 * (x - 1); }, "B");
  m.blocks.push_back({{flat(0.375, "A"), b}, {1, 2, 3}});
  return LayeredDomain(m);
}

TEST(LayeredDomain, APinchedOutLayerIsSkipped) {
  const LayeredDomain d = pinch_out();
  EXPECT_EQ(d.region({0.5, 0.5, 0.375}), 3);  // on both: the highest of 1, 2, 3
  EXPECT_EQ(d.region({0.5, 0.5, 0.38}), 3);
  EXPECT_EQ(d.region({0.5, 0.5, 0.37}), 1);
  EXPECT_EQ(d.region({1.5, 0.5, 0.45}), 2);
  EXPECT_EQ(d.region({1.5, 0.5, 0.375}), 2);
  EXPECT_EQ(d.region({1.5, 0.5, 0.5}), 3);
  EXPECT_EQ(d.region({1.5, 0.5, std::nextafter(0.5, 0.0)}), 2);
  EXPECT_EQ(d.regions(), (std::vector<Index>{1, 2, 3}));

  std::vector<Crossing> c = d.crossings({0.5, 0.5, 0.1}, {0.5, 0.5, 0.9});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].before, 1);
  EXPECT_EQ(c[0].after, 3);
  EXPECT_NEAR(c[0].t, 0.34375, 1e-15);
  c = d.crossings({1.5, 0.5, 0.1}, {1.5, 0.5, 0.9});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].after, 2);
  EXPECT_NEAR(c[1].point.z(), 0.5, 1e-15);
  EXPECT_EQ(c[1].after, 3);
  // Out of the wedge through B.
  c = d.crossings({0.5, 0.5, 0.45}, {1.5, 0.5, 0.45});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].before, 3);
  EXPECT_EQ(c[0].after, 2);
  EXPECT_NEAR(c[0].point.x(), 1.3, 1e-15);
  EXPECT_LT((c[0].normal - Vec3(0.25, 0, -1).normalized()).norm(), 1e-15);
  // Inside the contact every point is on both horizons (region 3), up to its end at x = 1.
  c = d.crossings({-0.5, 0.5, 0.375}, {1.5, 0.5, 0.375});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].before, 0);
  EXPECT_EQ(c[0].after, 3);
  EXPECT_EQ(c[1].before, 3);
  EXPECT_EQ(c[1].after, 2);
  EXPECT_NEAR(c[1].point.x(), 1.0, 1e-15);
}

TEST(LayeredDomain, ATouchFromBelowIsReportedWithBeforeEqualAfter) {
  // A valley z = 0.3 + 0.2 |x - 1| touched from below at its bottom line.
  LayeredModel m;
  m.box = kBox;
  m.blocks.push_back(
      {{graph_sheet(
           kBox, 2, 3, 2, [](double x, double) { return 0.3 + 0.2 * std::abs(x - 1); }, "valley")},
       {1, 2}});
  const LayeredDomain d(m);
  std::vector<Crossing> c = d.crossings({0.2, 0.5, 0.3}, {1.8, 0.5, 0.3});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].before, 1);
  EXPECT_EQ(c[0].after, 1);
  EXPECT_NEAR(c[0].t, 0.5, 1e-15);
  EXPECT_LT((c[0].normal - Vec3(0, 0, 1)).norm(), 1e-15);  // out of region 1, upward
  // From above, the touching point has the same (higher) label: nothing to report.
  LayeredModel ridge = m;
  ridge.blocks[0].horizons[0] = graph_sheet(
      kBox, 2, 3, 2, [](double x, double) { return 0.5 - 0.2 * std::abs(x - 1); }, "ridge");
  EXPECT_TRUE(LayeredDomain(ridge).crossings({0.2, 0.5, 0.5}, {1.8, 0.5, 0.5}).empty());
}

// The fault x = 0.375 + 0.25 z (dyadic, so that points on it are exact); z = 0.25 separates
// 1 and 2 on its lower side, z = 0.75 on its upper side (the layers are lifted there).
LayeredDomain faulted() {
  const Box3 box{Vec3::Zero(), Vec3::Ones()};
  LayeredModel m;
  m.box = box;
  m.faults.push_back(plane_sheet(box, 0, Vec3(0.375, 0, 0), Vec3(1, 0, -0.25), "fault"));
  m.blocks.push_back({{flat(0.25, "low", box)}, {1, 2}});
  m.blocks.push_back({{flat(0.75, "high", box)}, {1, 2}});
  return LayeredDomain(m);
}

TEST(LayeredDomain, AFaultOffsetsTheLayers) {
  const LayeredDomain d = faulted();
  const auto fault_x = [](double z) { return 0.375 + 0.25 * z; };
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 5000; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    if (std::abs(p.x() - fault_x(p.z())) < 1e-12) continue;
    const double horizon = p.x() < fault_x(p.z()) ? 0.25 : 0.75;
    ASSERT_EQ(d.region(p), p.z() >= horizon ? 2 : 1) << p.transpose();
  }
  // On the fault at z = 0.5: 2 on its lower side, 1 on its upper side; the higher wins.
  EXPECT_EQ(d.region({0.5, 0.3, 0.5}), 2);
  EXPECT_EQ(d.region({std::nextafter(0.5, 1.0), 0.3, 0.5}), 1);
  EXPECT_EQ(d.region({0.375, 0.3, 0.0}), 1);
  EXPECT_EQ(d.region({0.625, 0.3, 1.0}), 2);
  // Across the fault at z = 0.5: from 2 into 1, the normal is the fault's.
  const std::vector<Crossing> c = d.crossings({0.0, 0.5, 0.5}, {1.0, 0.5, 0.5});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].before, 2);
  EXPECT_EQ(c[0].after, 1);
  EXPECT_NEAR(c[0].t, 0.5, 1e-15);
  EXPECT_LT((c[0].normal - Vec3(1, 0, -0.25).normalized()).norm(), 1e-15);
  // Down the line x = 0.55: region 2 above the fault (z = 0.7), region 1 below it, where
  // the lifted horizon z = 0.75 lies above.
  const std::vector<Crossing> v = d.crossings({0.55, 0.5, 1.0}, {0.55, 0.5, 0.0});
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NEAR(v[0].point.z(), 0.7, 1e-15);
  EXPECT_EQ(v[0].before, 2);
  EXPECT_EQ(v[0].after, 1);
  EXPECT_EQ(d.regions(), (std::vector<Index>{1, 2}));
  EXPECT_LT((d.normal({0.51, 0.5, 0.5}) - Vec3(1, 0, -0.25).normalized()).norm(), 1e-15);
}

std::string error_of(const LayeredModel& m) {
  try {
    LayeredDomain d(m);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(LayeredDomain, CrossingHorizonsAreRefusedNamingBothAndAPoint) {
  LayeredModel m;
  m.box = kBox;
  m.name = "model.json";
  m.blocks.push_back(
      {{plane_sheet(kBox, 2, Vec3(1, 0, 0.5), Vec3(-0.2, 0, 1), "tilted"), flat(0.5, "flat")},
       {1, 2, 3}});
  EXPECT_EQ(error_of(m).rfind("model.json: horizons 'tilted' and 'flat' cross", 0), 0u)
      << error_of(m);
  // Equal heights everywhere are allowed (a layer of zero thickness).
  m.blocks[0].horizons = {flat(0.5, "a"), flat(0.5, "b")};
  EXPECT_EQ(error_of(m), "no error");

  // Vertices in order, edges crossing: a ridge along one diagonal (0.5) under a valley
  // along the other (0.4) cross at the centre.
  const Box3 unit{Vec3::Zero(), Vec3::Ones()};
  Sheet ridge{
      {{{0, 0, 0.5}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}}}, 2, "ridge"};
  Sheet valley{
      {{{0, 0, 0.6}, {1, 0, 0.4}, {1, 1, 0.6}, {0, 1, 0.4}}, {{0, 1, 3}, {1, 2, 3}}}, 2, "valley"};
  LayeredModel x;
  x.box = unit;
  x.blocks.push_back({{ridge, valley}, {1, 2, 3}});
  EXPECT_EQ(error_of(x),
            "layers: horizons 'ridge' and 'valley' cross (the layer between them would have "
            "a negative thickness) near (0.5, 0.5, 0.5)");
}

TEST(LayeredDomain, VerticesWithinFloatRoundingOfTheBorderAreMovedOntoIt) {
  // A horizon as an STL file stores it: the box [0, 0.3]^3 in float.
  const Box3 box{Vec3::Zero(), Vec3::Constant(0.3)};
  Sheet h = flat(0.15, "float", box);
  for (Vec3& p : h.surface.points) p = p.cast<float>().cast<double>();
  ASSERT_NE(h.surface.points[3].x(), 0.3);
  LayeredModel m;
  m.box = box;
  m.blocks.push_back({{h}, {1, 2}});
  const LayeredDomain d(m);
  EXPECT_EQ(d.region({0.3, 0.3, 0.1}), 1);
  EXPECT_EQ(d.region({0.3, 0.3, 0.2}), 2);
  // 1e-4 away is not rounding: refused.
  m.blocks[0].horizons[0].surface.points[3].x() = 0.3 - 1e-4;
  EXPECT_THROW(LayeredDomain{m}, InputError);
}

TEST(LayeredDomain, SheetsThatDoNotSpanTheBoxAreRefused) {
  const Box3 unit{Vec3::Zero(), Vec3::Ones()};
  const auto with = [&](Sheet s) {
    LayeredModel m;
    m.box = unit;
    m.blocks.push_back({{std::move(s)}, {1, 2}});
    return error_of(m);
  };
  Sheet holed = graph_sheet(
      unit, 2, 4, 4, [](double, double) { return 0.5; }, "holed");
  holed.surface.triangles.erase(holed.surface.triangles.begin() + 8);  // an inner one
  EXPECT_NE(with(holed).find("layers: sheet 'holed': edge"), std::string::npos) << with(holed);
  EXPECT_NE(with(holed).find("the sheet has a hole or does not span the box"), std::string::npos);

  Sheet half = flat(0.5, "half", Box3{Vec3::Zero(), Vec3(0.5, 1, 1)});
  EXPECT_NE(with(half).find("does not span the box"), std::string::npos) << with(half);

  Sheet outside = flat(0.5, "outside", Box3{Vec3::Zero(), Vec3(1.5, 1, 1)});
  EXPECT_NE(with(outside).find("lies outside the box's x-y rectangle"), std::string::npos);

  Sheet vertical{{{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}}, {{0, 1, 2}}}, 2, "wall"};
  EXPECT_NE(with(vertical).find("triangle 0 is vertical"), std::string::npos) << with(vertical);

  Sheet folded = graph_sheet(
      unit, 2, 3, 3, [](double, double) { return 0.5; }, "folded");
  std::swap(folded.surface.triangles[3][1], folded.surface.triangles[3][2]);
  EXPECT_NE(with(folded).find("folds over"), std::string::npos) << with(folded);

  Sheet twice = flat(0.5, "twice", unit);  // two copies, each spanning the box
  const TriSurface once = twice.surface;
  for (const Vec3& p : once.points) twice.surface.points.push_back(p);
  for (const auto& t : once.triangles)
    twice.surface.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  EXPECT_NE(with(twice).find("cover the box's x-y rectangle 2 times over"), std::string::npos)
      << with(twice);

  LayeredModel labels;
  labels.box = unit;
  labels.blocks.push_back({{flat(0.5, "a", unit)}, {1, 2, 3}});
  EXPECT_EQ(error_of(labels), "layers: 3 labels for the 1 horizons (expected one more)");
  LayeredModel box;
  box.box = Box3{Vec3::Zero(), Vec3(1, 0, 1)};
  box.blocks.push_back({{}, {1}});
  EXPECT_EQ(error_of(box), "layers: box: min must be below max in x, y and z (finite)");
}

}  // namespace
}  // namespace volmesh
