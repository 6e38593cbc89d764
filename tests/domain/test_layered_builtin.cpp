// builtin:layers6: its exact region volumes (integrated over the sheets' triangles) against
// the box volume, Monte-Carlo and exact chords; the pinch-out and the fault as the queries
// see them.
#include <gtest/gtest.h>

#include <cmath>

#include "test_analytic_support.hpp"
#include "volmesh/domain/builtin.hpp"

namespace volmesh {
namespace {

const Domain& layers6() {
  static const std::unique_ptr<Domain> d = make_builtin_domain("layers6");
  return *d;
}

TEST(Layers6, VolumesAddUpToTheBoxAndMatchMonteCarloAndChords) {
  const std::map<Index, double> v = builtin_region_volumes("layers6");
  ASSERT_EQ(v.size(), 6u);
  double total = 0.0;
  for (const auto& [label, volume] : v) {
    EXPECT_GT(volume, 0.05) << "layer " << label;
    total += volume;
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  // 4 sigma of 40,000 samples is about 1% of a layer; 64 x 64 exact chords along x (the
  // midpoint rule across them errs by 2.8e-3 at most, 2.2e-4 with 96 x 96).
  test::expect_region_volumes(layers6(), v, 40000, 64, 5e-3);
}

// The horizons' heights seen by a vertical line: the crossings from the bottom up.
std::vector<Crossing> column(double x, double y) {
  return layers6().crossings({x, y, -0.5}, {x, y, 1.5});
}

TEST(Layers6, LayerThreePinchesOutWhereYIsSmall) {
  // x = 0.1 lies wholly below the fault's lower side (the fault is x = 0.4 + 0.3 z).
  std::vector<Index> low, high;
  for (const Crossing& c : column(0.1, 0.05)) low.push_back(c.after);
  for (const Crossing& c : column(0.1, 0.9)) high.push_back(c.after);
  EXPECT_EQ(low, (std::vector<Index>{1, 2, 4, 5, 6, 0}));
  EXPECT_EQ(high, (std::vector<Index>{1, 2, 3, 4, 5, 6, 0}));
}

TEST(Layers6, ColumnsCrossTheHorizonsUpwardAndTheFaultAlongItsNormal) {
  // x = 0.125 lies wholly on the fault's lower side, 0.875 on its upper side; the others
  // pass through the fault. (The lift itself is checked by the exact volumes.)
  const Vec3 fault_normal = Vec3(1, 0, -0.3).normalized();
  int fault_crossings = 0;
  for (double x : {0.125, 0.5, 0.6, 0.875})
    for (double y : {0.25, 0.75}) {
      const std::vector<Crossing> c = column(x, y);
      ASSERT_GE(c.size(), 6u);
      Index current = 0;
      for (const Crossing& k : c) {
        EXPECT_EQ(k.before, current);
        current = k.after;
        if (k.point.z() == 0.0 || k.point.z() == 1.0) continue;
        const bool on_fault = std::abs(k.point.x() - (0.4 + 0.3 * k.point.z())) < 1e-12;
        if (on_fault) {
          ++fault_crossings;
          EXPECT_LT(std::abs(std::abs(k.normal.dot(fault_normal)) - 1.0), 1e-12);
        } else {
          EXPECT_GT(k.normal.z(), 0.5);
          EXPECT_GT(k.after, k.before);
        }
      }
      EXPECT_EQ(current, 0);
    }
  EXPECT_GT(fault_crossings, 0);
}

TEST(Layers6, RegionsAndBounds) {
  EXPECT_EQ(layers6().regions(), (std::vector<Index>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(layers6().bounds().lo, Vec3::Zero());
  EXPECT_EQ(layers6().bounds().hi, Vec3::Ones());
  EXPECT_EQ(layers6().region({0.5, 0.5, 1e-9}), 1);
  EXPECT_EQ(layers6().region({0.5, 0.5, 1 - 1e-9}), 6);
}

}  // namespace
}  // namespace volmesh
