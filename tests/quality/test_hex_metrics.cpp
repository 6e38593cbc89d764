#include <gtest/gtest.h>

#include <cmath>

#include "volmesh/quality/hex_metrics.hpp"

namespace volmesh {
namespace {

std::array<Vec3, 8> unit_cube() {
  return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
          Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
}

TEST(HexScaledJacobian, UnitCubeIsOne) { EXPECT_DOUBLE_EQ(hex_scaled_jacobian(unit_cube()), 1.0); }

TEST(HexScaledJacobian, StretchedBoxIsOne) {
  auto h = unit_cube();
  for (Vec3& p : h) p = p.cwiseProduct(Vec3(1, 2, 30)) + Vec3(5, 6, 7);
  EXPECT_DOUBLE_EQ(hex_scaled_jacobian(h), 1.0);
}

TEST(HexScaledJacobian, ShearedHexIsTheCosineOfTheShear) {
  // Top shifted by (1, 0) over a height of 1: every corner and the centre see the edges
  // (1,0,0), (0,1,0), (1,0,1), whose scaled determinant is 1/sqrt(2).
  auto h = unit_cube();
  for (int k = 4; k < 8; ++k) h[k].x() += 1.0;
  EXPECT_NEAR(hex_scaled_jacobian(h), 1.0 / std::sqrt(2.0), 1e-15);
}

TEST(HexScaledJacobian, TrapezoidalHexIsTwoOverSqrtFive) {
  // Top face narrowed to x in [0, 0.5]: the corners at x = 1 (bottom) and x = 0.5 (top) see
  // a slanted edge (-0.5, 0, 1) at right angles to the other two: 1 / |(-0.5, 0, 1)|.
  // The centre gives 48 / (3·4·sqrt 17) ≈ 0.970, the other corners 1.
  auto h = unit_cube();
  h[5].x() = h[6].x() = 0.5;
  EXPECT_NEAR(hex_scaled_jacobian(h), 2.0 / std::sqrt(5.0), 1e-15);
}

TEST(HexScaledJacobian, CollapsedEdgeIsDegenerateNotPerfect) {
  // Verdict returns DBL_MAX here; the hex has lost an edge and is degenerate.
  auto h = unit_cube();
  h[5] = h[1];
  EXPECT_EQ(hex_scaled_jacobian(h), 0.0);
  h = unit_cube();
  h[5] = h[1] + Vec3(1e-14, 0, 0);  // collapsed up to rounding
  EXPECT_EQ(hex_scaled_jacobian(h), 0.0);
}

TEST(HexScaledJacobian, PointHexIsDegenerate) {
  std::array<Vec3, 8> h;
  h.fill(Vec3(1, 2, 3));
  EXPECT_EQ(hex_scaled_jacobian(h), 0.0);
}

TEST(HexScaledJacobian, InvertedHexIsNegative) {
  // Corner 4 pushed below the base: at corner 0 the edges are (1,0,0), (0,1,0), (0,0,-0.5).
  auto h = unit_cube();
  h[4] = Vec3(0, 0, -0.5);
  EXPECT_DOUBLE_EQ(hex_scaled_jacobian(h), -1.0);
  // The mirror image of a valid hex is inverted everywhere.
  h = unit_cube();
  for (Vec3& p : h) p.z() = -p.z();
  EXPECT_DOUBLE_EQ(hex_scaled_jacobian(h), -1.0);
}

TEST(HexScaledJacobian, FlatCornerIsZero) {
  // Corner 4 moved onto the base plane's extension: the three edges at corner 0 are coplanar.
  auto h = unit_cube();
  h[4] = Vec3(-1, -1, 0);
  EXPECT_EQ(hex_scaled_jacobian(h), 0.0);
}

}  // namespace
}  // namespace volmesh
