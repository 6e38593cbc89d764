// How faces are cut into triangles: the fan around the vertex average when it faces one way,
// an ear clipping that covers a non-convex face once, and a verdict of folded when no split
// of a self-overlapping face avoids crossing itself.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "volmesh/geometry/polygon_split.hpp"

namespace volmesh {
namespace {

std::vector<Index> whole_loop(const std::vector<Vec3>& points) {
  std::vector<Index> loop(points.size());
  std::iota(loop.begin(), loop.end(), 0);
  return loop;
}

// The area vectors of the triangles, corner loop.size() being the vertex average.
std::vector<Vec3> triangle_areas(const std::vector<Vec3>& points, const PolygonSplit& split) {
  Vec3 average = Vec3::Zero();
  for (const Vec3& p : points) average += p;
  average /= static_cast<double>(points.size());
  const auto corner = [&](int k) {
    return k == static_cast<int>(points.size()) ? average : points[k];
  };
  std::vector<Vec3> areas;
  for (const auto& t : split.triangles)
    areas.push_back(0.5 * (corner(t[1]) - corner(t[0])).cross(corner(t[2]) - corner(t[0])));
  return areas;
}

TEST(PolygonSplit, AConvexFaceKeepsTheFanAroundItsVertexAverage) {
  const std::vector<Vec3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const PolygonSplit split = split_polygon(square, whole_loop(square));
  EXPECT_TRUE(split.triangles.empty());
  EXPECT_FALSE(split.folded);

  const auto fan = fan_triangles(4);
  ASSERT_EQ(fan.size(), 4u);
  for (std::size_t k = 0; k < fan.size(); ++k)
    EXPECT_EQ(fan[k], (std::array<int, 3>{static_cast<int>(k), static_cast<int>((k + 1) % 4), 4}));
}

TEST(PolygonSplit, ANonConvexFaceIsEarClippedIntoPositiveTrianglesCoveringItOnce) {
  // A U whose vertex average (1.5, 1.5) lies in the notch, outside the face: area 9 - 2 = 7.
  const std::vector<Vec3> u = {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {2, 3, 0},
                               {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};
  const PolygonSplit split = split_polygon(u, whole_loop(u));
  EXPECT_FALSE(split.folded);
  ASSERT_EQ(split.triangles.size(), u.size() - 2);  // an ear clipping, not the fan
  double area = 0.0;
  for (const Vec3& a : triangle_areas(u, split)) {
    EXPECT_GT(a.z(), 0.0);  // each faces the way the face does
    area += a.z();
  }
  EXPECT_NEAR(area, 7.0, 1e-12);
}

TEST(PolygonSplit, AFaceOverlappingItselfIsFolded) {
  // A quadrilateral whose last side runs back across the first: every split crosses itself.
  const std::vector<Vec3> bow = {{0, 0, 0}, {4, 0, 0}, {0, 2, 0}, {3, -1, 0}};
  const PolygonSplit split = split_polygon(bow, whole_loop(bow));
  EXPECT_TRUE(split.folded);
  EXPECT_TRUE(split.triangles.empty());
}

}  // namespace
}  // namespace volmesh
