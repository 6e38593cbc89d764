// The one retry order of projection directions (directions.hpp): the first axis, tilted once,
// the other axes, the remaining tilts; no direction twice.
#include <gtest/gtest.h>

#include <set>
#include <utility>
#include <vector>

#include "volmesh/tet/directions.hpp"

namespace volmesh::tet {
namespace {

TEST(ProjectionDirections, EveryAxisThenTheFirstOnesTiltsEachOnce) {
  for (const Axis first : {Axis::x, Axis::y, Axis::z}) {
    const std::vector<ProjectionOptions> d = projection_directions(first);
    ASSERT_EQ(d.size(), static_cast<std::size_t>(3 + kTilts));
    EXPECT_EQ(d[0].axis, first);
    EXPECT_EQ(d[0].tilt, 0);
    EXPECT_EQ(d[1].axis, first);
    EXPECT_EQ(d[1].tilt, 1);
    std::set<std::pair<Axis, int>> seen;
    std::set<Axis> untilted;
    for (const ProjectionOptions& o : d) {
      EXPECT_FALSE(o.auto_axis);
      EXPECT_TRUE(seen.insert({o.axis, o.tilt}).second)
          << direction_name(o.axis, o.tilt) << " twice";
      if (o.tilt == 0) untilted.insert(o.axis);
      else EXPECT_EQ(o.axis, first);  // only the first axis is tilted
    }
    EXPECT_EQ(untilted.size(), 3u);
    // The other axes before the remaining tilts, in the order z, x, y.
    std::vector<Axis> others;
    for (const Axis a : {Axis::z, Axis::x, Axis::y})
      if (a != first) others.push_back(a);
    EXPECT_EQ(d[2].axis, others[0]);
    EXPECT_EQ(d[3].axis, others[1]);
    EXPECT_EQ(d[2].tilt + d[3].tilt, 0);
  }
}

}  // namespace
}  // namespace volmesh::tet
