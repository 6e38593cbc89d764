#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "volmesh/quality/tet_metrics.hpp"

namespace volmesh {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// Regular tet with edge 2·sqrt(2), positively oriented.
const Vec3 a(1, 1, 1), b(1, -1, -1), c(-1, -1, 1), d(-1, 1, -1);

TEST(TetMetrics, RegularTetHasTheTextbookValues) {
  const TetMetrics m = tet_metrics(a, b, c, d);
  EXPECT_NEAR(m.min_dihedral_deg, std::acos(1.0 / 3.0) * kDeg, 1e-12);
  EXPECT_NEAR(m.max_dihedral_deg, 70.528779365509308, 1e-12);
  EXPECT_NEAR(m.radius_edge_ratio, std::sqrt(6.0) / 4.0, 1e-14);
  EXPECT_NEAR(m.radius_edge_ratio, 0.6124, 1e-4);
  EXPECT_NEAR(m.aspect_ratio, 1.0, 1e-14);
  EXPECT_NEAR(m.volume, 8.0 / 3.0, 1e-14);
}

TEST(TetMetrics, FlippedTetHasNegativeVolumeAndTheSameShape) {
  const TetMetrics m = tet_metrics(a, b, d, c);
  EXPECT_NEAR(m.volume, -8.0 / 3.0, 1e-14);
  EXPECT_NEAR(m.min_dihedral_deg, std::acos(1.0 / 3.0) * kDeg, 1e-12);
  EXPECT_NEAR(m.radius_edge_ratio, std::sqrt(6.0) / 4.0, 1e-14);
  EXPECT_NEAR(m.aspect_ratio, 1.0, 1e-14);
}

TEST(TetMetrics, KuhnTetHasRightAndHalfRightDihedrals) {
  // The path simplex of the unit cube: dihedral angles 90° (x3), 60° (x2), 45°; the
  // circumcentre is the cube centre, so R = sqrt(3)/2 over a shortest edge of 1.
  const TetMetrics m = tet_metrics({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1});
  EXPECT_NEAR(m.min_dihedral_deg, 45.0, 1e-12);
  EXPECT_NEAR(m.max_dihedral_deg, 90.0, 1e-12);
  EXPECT_NEAR(m.radius_edge_ratio, std::sqrt(3.0) / 2.0, 1e-14);
  // Inradius 3V / area = 0.5 / (1 + sqrt 2).
  EXPECT_NEAR(m.aspect_ratio, std::sqrt(3.0) * (1.0 + std::sqrt(2.0)) / 3.0, 1e-14);
  EXPECT_NEAR(m.volume, 1.0 / 6.0, 1e-15);
}

TEST(TetMetrics, MetricsAreScaleAndTranslationInvariant) {
  const Vec3 t(10, -3, 7);
  const TetMetrics m = tet_metrics(3 * a + t, 3 * b + t, 3 * c + t, 3 * d + t);
  EXPECT_NEAR(m.radius_edge_ratio, std::sqrt(6.0) / 4.0, 1e-13);
  EXPECT_NEAR(m.aspect_ratio, 1.0, 1e-13);
  EXPECT_NEAR(m.volume, 27 * 8.0 / 3.0, 1e-11);
}

TEST(TetMetrics, FlatTetIsInfinitelyBad) {
  // A unit square: the diagonal edges see the other two corners on opposite sides (180°),
  // the side edges see them on the same side (0°).
  const TetMetrics m = tet_metrics({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0});
  EXPECT_EQ(m.volume, 0.0);
  EXPECT_NEAR(m.min_dihedral_deg, 0.0, 1e-12);
  EXPECT_NEAR(m.max_dihedral_deg, 180.0, 1e-12);
  EXPECT_TRUE(std::isinf(m.radius_edge_ratio));
  EXPECT_TRUE(std::isinf(m.aspect_ratio));
}

TEST(TetMetrics, SliverHasSmallAndLargeDihedralsAndLargeAspect) {
  // The four corners of a square lifted alternately by ±eps: nearly flat, well-spaced.
  const double eps = 1e-3;
  const TetMetrics m = tet_metrics({0, 0, -eps}, {1, 0, eps}, {1, 1, -eps}, {0, 1, eps});
  EXPECT_LT(m.min_dihedral_deg, 1.0);
  EXPECT_GT(m.max_dihedral_deg, 179.0);
  EXPECT_NEAR(m.radius_edge_ratio, std::sqrt(0.5), 1e-5);  // well spaced: Delaunay misses it
  EXPECT_GT(m.aspect_ratio, 100.0);
}

}  // namespace
}  // namespace volmesh
