#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <utility>

#include "volmesh/core/geometry.hpp"
#include "volmesh/hexdc/hex_quality.hpp"

namespace volmesh {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

std::array<Vec3, 8> unit_cube() {
  return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
          Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
}

TEST(HexCornerTets, UnitCubeHasEightCornerSixthsAndTwoInnerThirds) {
  const auto volumes = hex_corner_tet_volumes(unit_cube());
  int corners = 0, inner = 0;
  for (const double v : volumes) {
    if (std::abs(v - 1.0 / 6.0) < 1e-15) ++corners;
    if (std::abs(v - 1.0 / 3.0) < 1e-15) ++inner;
  }
  EXPECT_EQ(corners, 8);
  EXPECT_EQ(inner, 2);
  // Each five-tet split fills the cube: four corners and one inner tet per split.
  EXPECT_NEAR(std::accumulate(volumes.begin(), volumes.end(), 0.0), 2.0, 1e-15);
}

// Corner 0 of a cube of side 0.1 moved onto the plane of its three edge neighbours: its corner
// tet is exactly flat in these doubles, which the doubles' own volume calls positive (by
// rounding). The exact test refuses the hex; the other nine tets are positive.
TEST(HexCornerTets, ExactlyFlatCornerTetFailsWhereTheDoublesSayPositive) {
  std::array<Vec3, 8> hex{Vec3(0.16, 0.11000000000000001, 0.13), Vec3(0.2, 0.1, 0.1),
                          Vec3(0.2, 0.2, 0.1), Vec3(0.1, 0.2, 0.1), Vec3(0.1, 0.1, 0.2),
                          Vec3(0.2, 0.1, 0.2), Vec3(0.2, 0.2, 0.2), Vec3(0.1, 0.2, 0.2)};
  const auto volumes = hex_corner_tet_volumes(hex);
  EXPECT_GT(volumes[0], 0.0);
  EXPECT_TRUE(std::all_of(volumes.begin() + 1, volumes.end(), [](double v) { return v > 1e-6; }));
  EXPECT_FALSE(hex_corner_tets_positive(hex));
  EXPECT_FALSE(hex_grade(hex).corner_tets_positive);
  EXPECT_FALSE(hex_quality(hex).corner_tets_positive);
  // One unit in the last place off the plane, far less than the doubles' rounding of the
  // volume: valid on the cube's side of it, folded across it.
  const double z = hex[0].z();
  hex[0].z() = std::nextafter(z, 0.0);
  EXPECT_TRUE(hex_corner_tets_positive(hex));
  hex[0].z() = std::nextafter(z, 1.0);
  EXPECT_FALSE(hex_corner_tets_positive(hex));
}

TEST(HexQuality, UnitCubeIsValidWithScaledJacobianOne) {
  const HexQuality q = hex_quality(unit_cube());
  EXPECT_TRUE(q.corner_tets_positive);
  EXPECT_DOUBLE_EQ(q.scaled_jacobian, 1.0);
  EXPECT_NEAR(q.max_quad_angle_deg, 90.0, 1e-12);
  EXPECT_NEAR(q.max_quad_distortion_deg, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(q.min_edge, 1.0);
  EXPECT_DOUBLE_EQ(q.max_edge, 1.0);
}

TEST(HexQuality, ParallelepipedHasTheScaledJacobianOfItsEdges) {
  // Top shifted by (0.5, 0.5): at every corner and the centre the edges are (1,0,0), (0,1,0),
  // (0.5,0.5,1) up to sign, determinant 1, lengths 1, 1, sqrt(1.5). The side faces are
  // parallelograms whose obtuse angle has the cosine -0.5 / sqrt(1.5).
  auto h = unit_cube();
  for (int k = 4; k < 8; ++k) h[k] += Vec3(0.5, 0.5, 0.0);
  const HexQuality q = hex_quality(h);
  EXPECT_TRUE(q.corner_tets_positive);
  EXPECT_NEAR(q.scaled_jacobian, 1.0 / std::sqrt(1.5), 1e-15);
  const double obtuse = std::acos(-0.5 / std::sqrt(1.5)) * kDegPerRad;
  EXPECT_NEAR(q.max_quad_angle_deg, obtuse, 1e-12);
  EXPECT_NEAR(q.max_quad_distortion_deg, obtuse - 90.0, 1e-12);
  EXPECT_DOUBLE_EQ(q.min_edge, 1.0);
  EXPECT_NEAR(q.max_edge, std::sqrt(1.5), 1e-15);
}

TEST(HexQuality, SwappedTopCornersAreFolded) {
  auto h = unit_cube();
  std::swap(h[6], h[7]);
  const HexQuality q = hex_quality(h);
  EXPECT_FALSE(q.corner_tets_positive);
  EXPECT_LE(q.scaled_jacobian, 0.0);
}

TEST(HexQuality, CornerPushedThroughTheOppositeFaceIsFolded) {
  // Corner 6 moved below the bottom face: the tet at corner 2 (edges to 3, 1 and 6) turns over.
  auto h = unit_cube();
  h[6] = Vec3(1, 1, -0.5);
  const auto volumes = hex_corner_tet_volumes(h);
  EXPECT_LT(*std::min_element(volumes.begin(), volumes.end()), 0.0);
  EXPECT_FALSE(hex_corner_tets_positive(h));
}

TEST(HexQuality, NonPlanarFacesWithPositiveTetsAreValid) {
  // Top quad turned by 20° about the vertical axis and corner 6 raised: no face but the
  // bottom is planar, yet all ten tets stay positive.
  auto h = unit_cube();
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(20.0 / kDegPerRad, Vec3::UnitZ()).toRotationMatrix();
  const Vec3 axis(0.5, 0.5, 0.0);
  for (int k = 4; k < 8; ++k) h[k] = axis + turn * (h[k] - axis);
  h[6].z() += 0.3;
  ASSERT_GT(std::abs(tet_volume(h[4], h[5], h[6], h[7])), 1e-3);  // the top is not planar
  ASSERT_GT(std::abs(tet_volume(h[1], h[2], h[6], h[5])), 1e-3);  // nor a side
  const HexQuality q = hex_quality(h);
  EXPECT_TRUE(q.corner_tets_positive);
  EXPECT_GT(q.scaled_jacobian, 0.0);
  EXPECT_LT(q.scaled_jacobian, 1.0);
}

TEST(HexQuality, RhombusPrismHasThirtyDegreesOfDistortion) {
  // A prism over a rhombus of side 1 and angles 60° and 120°.
  const double h = std::sqrt(3.0) / 2.0;
  std::array<Vec3, 8> prism{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1.5, h, 0), Vec3(0.5, h, 0)};
  for (int k = 0; k < 4; ++k) prism[k + 4] = prism[k] + Vec3::UnitZ();
  const HexQuality q = hex_quality(prism);
  EXPECT_TRUE(q.corner_tets_positive);
  EXPECT_NEAR(q.max_quad_angle_deg, 120.0, 1e-12);
  EXPECT_NEAR(q.max_quad_distortion_deg, 30.0, 1e-12);
  EXPECT_NEAR(q.scaled_jacobian, h, 1e-15);
}

TEST(QuadAngles, DartHasAReflexCornerWhicheverWayRound) {
  // The dart (0,0), (2,0), (0.5,0.5), (0,2): its reflex corner sees its neighbours 126.87°
  // apart (cosine -0.6), so its interior angle is the rest of the full turn.
  const std::array<Vec3, 4> dart{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0.5, 0.5, 0), Vec3(0, 2, 0)};
  const std::array<Vec3, 4> reversed{dart[3], dart[2], dart[1], dart[0]};
  const double reflex = 360.0 - std::acos(-0.6) * kDegPerRad;
  for (const auto& quad : {dart, reversed}) {
    const auto angles = quad_interior_angles_deg(quad);
    EXPECT_NEAR(*std::max_element(angles.begin(), angles.end()), reflex, 1e-12);
    EXPECT_NEAR(std::accumulate(angles.begin(), angles.end(), 0.0), 360.0, 1e-12);
  }
}

}  // namespace
}  // namespace volmesh
