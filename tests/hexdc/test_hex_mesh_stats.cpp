#include <gtest/gtest.h>

#include <cmath>

#include "volmesh/hexdc/hex_mesh_stats.hpp"

namespace volmesh {
namespace {

// Two unit cubes side by side along x, the second stretched to length `length`.
HexMesh two_boxes(double length) {
  HexMesh mesh;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (const double x : {0.0, 1.0, 1.0 + length}) mesh.points.emplace_back(x, j, k);
  // Point (i, j, k) is at i + 3 j + 6 k.
  const auto p = [](Index i, Index j, Index k) { return i + 3 * j + 6 * k; };
  for (Index i = 0; i < 2; ++i)
    mesh.cells.push_back({p(i, 0, 0), p(i + 1, 0, 0), p(i + 1, 1, 0), p(i, 1, 0), p(i, 0, 1),
                          p(i + 1, 0, 1), p(i + 1, 1, 1), p(i, 1, 1)});
  mesh.cell_region = {1, 1};
  return mesh;
}

TEST(HexMeshStats, TwoUnitCubesAreTheIdealRow) {
  const HexMeshStats s = hex_mesh_stats(two_boxes(1.0));
  EXPECT_EQ(s.nodes, 12);
  EXPECT_EQ(s.cells, 2);
  EXPECT_DOUBLE_EQ(s.min_edge, 1.0);
  EXPECT_DOUBLE_EQ(s.max_edge, 1.0);
  EXPECT_DOUBLE_EQ(s.max_aspect_ratio, 1.0);
  EXPECT_NEAR(s.max_quad_distortion_deg, 0.0, 1e-12);
  EXPECT_NEAR(s.min_scaled_jacobian, 1.0, 1e-12);
  EXPECT_NEAR(s.mean_scaled_jacobian, 1.0, 1e-12);
  EXPECT_EQ(s.degenerate, 0);
  EXPECT_EQ(s.first_degenerate, kNoIndex);
  // Eight outer corners in one hex, the four nodes of the shared face in two.
  EXPECT_EQ(s.valence, (std::map<Index, Index>{{1, 8}, {2, 4}}));
}

TEST(HexMeshStats, AStretchedBoxSetsTheEdgesAndAspectRatio) {
  const HexMeshStats s = hex_mesh_stats(two_boxes(4.0));
  EXPECT_DOUBLE_EQ(s.min_edge, 1.0);
  EXPECT_DOUBLE_EQ(s.max_edge, 4.0);
  EXPECT_DOUBLE_EQ(s.max_aspect_ratio, 4.0);
  EXPECT_NEAR(s.min_scaled_jacobian, 1.0, 1e-12);  // a box is still right-angled
}

TEST(HexMeshStats, AFoldedHexIsDegenerateAndNamed) {
  HexMesh mesh = two_boxes(1.0);
  // Push the second cube's top corner (2, 1, 1) through its bottom face.
  mesh.points[2 + 3 + 6] = Vec3(1.5, 0.5, -0.5);
  const HexMeshStats s = hex_mesh_stats(mesh);
  EXPECT_EQ(s.degenerate, 1);
  EXPECT_EQ(s.first_degenerate, 1);
  EXPECT_LT(s.min_scaled_jacobian, 0.0);
  EXPECT_GT(s.first_degenerate_centre.x(), 1.0);
}

TEST(HexMeshStats, AnEmptyMeshIsAllZero) {
  const HexMeshStats s = hex_mesh_stats(HexMesh{});
  EXPECT_EQ(s.cells, 0);
  EXPECT_EQ(s.nodes, 0);
  EXPECT_TRUE(s.valence.empty());
}

}  // namespace
}  // namespace volmesh
