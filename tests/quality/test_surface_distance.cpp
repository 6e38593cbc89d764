#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "volmesh/quality/surface_distance.hpp"

namespace volmesh {
namespace {

// The unit square in z = 0 as an n × n grid of squares, each cut along the diagonal from
// (i, j) to (i+1, j+1); `hole` squares left out (by index j * n + i).
TriSurface square_grid(int n, std::vector<int> holes = {}) {
  TriSurface s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s.points.emplace_back(double(i) / n, double(j) / n, 0.0);
  const auto at = [n](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (std::find(holes.begin(), holes.end(), j * n + i) != holes.end()) continue;
      s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return s;
}

// The same square as two triangles cut along the other diagonal, which crosses every
// diagonal of the grid.
TriSurface square_two_triangles() {
  TriSurface s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  s.triangles = {{0, 1, 3}, {1, 2, 3}};
  return s;
}

// Subdividing the pieces that straddle two coplanar triangles down to the error bound would
// take 1e9 pieces per crossed edge here (hours); the coplanar cover bound settles them at
// once, which is what lets this test finish.
TEST(SurfaceDistance, CoincidingPlanarTriangulationsAreAtDistanceZero) {
  const HausdorffDistance d = hausdorff_distance(square_grid(64), square_two_triangles(), 1e-9);
  EXPECT_LT(d.from_a, 1e-15);
  EXPECT_LT(d.from_b, 1e-15);
}

// The same with the grid's points off the plane by up to a tenth of the bound, as rounding
// leaves a mesh boundary on a planar face.
TEST(SurfaceDistance, NearlyCoincidingPlanarTriangulationsAreMeasured) {
  TriSurface grid = square_grid(64);
  for (std::size_t i = 0; i < grid.points.size(); ++i) grid.points[i].z() = 1e-10 * std::sin(double(i));
  const HausdorffDistance d = hausdorff_distance(grid, square_two_triangles(), 1e-9);
  EXPECT_LE(d.from_a, 1e-10);
  EXPECT_LE(d.from_b, 1e-10);
}

// A hole in the grid is not covered: the square's points over it are as far from the grid as
// the hole's centre is from its rim, half a cell.
TEST(SurfaceDistance, AHoleUnderAPlanarPieceIsNotCovered) {
  const int n = 8;
  const HausdorffDistance d = hausdorff_distance(square_grid(n, {3 * n + 4}), square_two_triangles(), 1e-9);
  EXPECT_LT(d.from_a, 1e-15);
  EXPECT_NEAR(d.from_b, 0.5 / n, 1e-9);
}

// The farthest point from the surface can lie inside a triangle whose corners are on it: a
// triangle across the middle of the cube [-1, 1]^3 with its corners on the cube's edges is 1
// from the cube's faces at the centre, and 0 at its corners.
TEST(SurfaceDistance, FindsTheFarthestPointInsideATriangle) {
  TriSurface cube;
  for (int k = 0; k < 8; ++k) cube.points.emplace_back(k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0);
  cube.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  TriSurface across;
  across.points = {{-1, -1, 0}, {1, -1, 0}, {0.3, 1, 0}};
  across.triangles = {{0, 1, 2}};
  const HausdorffDistance d = hausdorff_distance(across, cube, 1e-9);
  EXPECT_NEAR(d.from_a, 1.0, 1e-9);
  EXPECT_LE(d.from_a, 1.0);
}

}  // namespace
}  // namespace volmesh
