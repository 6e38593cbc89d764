// Self-intersections of triangle soups: the pairs found, in the input numbering, for each way
// two triangles can meet (sharing nothing, a vertex, an edge or everything).
#include <gtest/gtest.h>

#include "../support/surfaces.hpp"
#include "volmesh/geometry/self_intersections.hpp"

namespace volmesh {
namespace {

using Pairs = std::vector<std::pair<Index, Index>>;

Pairs intersections(const TriSurface& s) {
  bool truncated = true;
  Pairs pairs = find_self_intersections(s, 100, &truncated);
  EXPECT_FALSE(truncated);
  return pairs;
}

// The triangle (0,0,0) (1,0,0) (0,1,0) as vertices 0-2, then `more` points.
TriSurface base_triangle_and(std::vector<Vec3> more) {
  TriSurface s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  s.points.insert(s.points.end(), more.begin(), more.end());
  s.triangles = {{0, 1, 2}};
  return s;
}

TEST(SurfaceSelfIntersections, ClosedSurfacesHaveNone) {
  EXPECT_TRUE(intersections(test::unit_cube()).empty());
  EXPECT_TRUE(intersections(test::icosphere(3)).empty());
}

TEST(SurfaceSelfIntersections, TrianglesSharingAnEdgeIntersectOnlyWhenFoldedOntoEachOther) {
  TriSurface s = base_triangle_and({{0.2, 0.2, 0}, {1, 1, 0}, {0.3, 0.3, 1}});
  s.triangles.push_back({2, 1, 3});  // 1: coplanar, same side of edge 1-2 as vertex 0
  s.triangles.push_back({2, 1, 4});  // 2: coplanar, other side
  s.triangles.push_back({2, 1, 5});  // 3: bent out of the plane
  EXPECT_EQ(intersections(s), (Pairs{{0, 1}}));
}

TEST(SurfaceSelfIntersections, TrianglesSharingAVertexIntersectWhenOnePierces) {
  TriSurface s = base_triangle_and({{0.5, 0.2, -1}, {0.2, 0.5, 1}, {-1, -1, 1}, {-1, -2, 1}});
  s.triangles.push_back({0, 3, 4});  // 1: through the base triangle's interior
  s.triangles.push_back({0, 5, 6});  // 2: touches it only at vertex 0
  EXPECT_EQ(intersections(s), (Pairs{{0, 1}}));
}

TEST(SurfaceSelfIntersections, DisjointIndicesIntersectWhenTouchingOrCrossing) {
  TriSurface s = base_triangle_and({{0.25, 0.25, -1},
                                    {0.25, 0.25, 1},
                                    {0.3, 0.4, 1},
                                    {0.5, 0.5, 0},
                                    {0.5, 0.5, 1},
                                    {0.6, 0.6, 1},
                                    {5, 5, 5},
                                    {6, 5, 5},
                                    {5, 6, 5}});
  s.triangles.push_back({3, 4, 5});    // 1: crosses the base triangle
  s.triangles.push_back({6, 7, 8});    // 2: touches its edge 1-2 at one point
  s.triangles.push_back({9, 10, 11});  // 3: far away
  s.triangles.push_back({0, 2, 1});    // 4: the base triangle again, reversed
  EXPECT_EQ(intersections(s), (Pairs{{0, 1}, {0, 2}, {0, 4}, {1, 4}, {2, 4}}));
}

TEST(SurfaceSelfIntersections, DegenerateTrianglesAreLeftToTheChecker) {
  TriSurface s = base_triangle_and({{0.5, 0.5, 0}, {2, 2, 0}});
  s.triangles.push_back({0, 3, 4});  // collinear, lying across the base triangle
  EXPECT_TRUE(intersections(s).empty());
}

TEST(SurfaceSelfIntersections, StopsAfterMaxPairs) {
  TriSurface s = base_triangle_and({});
  for (int k = 0; k < 5; ++k) s.triangles.push_back({0, 1, 2});
  bool truncated = false;
  EXPECT_EQ(find_self_intersections(s, 3, &truncated).size(), 3u);
  EXPECT_TRUE(truncated);
  EXPECT_EQ(find_self_intersections(s, 15, &truncated).size(), 15u);
  EXPECT_FALSE(truncated);
  EXPECT_TRUE(find_self_intersections(s, 0, &truncated).empty());
  EXPECT_TRUE(truncated);
}

}  // namespace
}  // namespace volmesh
