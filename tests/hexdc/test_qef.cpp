#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "volmesh/hexdc/qef.hpp"

namespace volmesh {
namespace {

const Eigen::AlignedBox3d kUnitNode(Vec3::Zero(), Vec3::Ones());

Vec3 mass_point(const std::vector<EdgeCrossing>& crossings) {
  Vec3 sum = Vec3::Zero();
  for (const EdgeCrossing& c : crossings) sum += c.point;
  return sum / static_cast<double>(crossings.size());
}

TEST(Qef, ThreeOrthogonalPlanesGiveTheirCorner) {
  // Three mutually orthogonal planes in a rotated frame through c, two crossings on each,
  // none at c: the only zero of E is c.
  const Vec3 c(0.45, 0.5, 0.55);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<EdgeCrossing> crossings;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 n = r.col(axis), u = r.col((axis + 1) % 3), v = r.col((axis + 2) % 3);
    crossings.push_back({c + 0.2 * u - 0.1 * v, n});
    crossings.push_back({c - 0.15 * u + 0.25 * v, n});
  }
  const QefVertex x = solve_qef(crossings, kUnitNode);
  EXPECT_EQ(x.rank, 3);
  EXPECT_FALSE(x.fell_back);
  EXPECT_LT((x.point - c).norm(), 1e-12);
}

TEST(Qef, TwoParallelPlanesGiveThePointNearestTheMassPoint) {
  // A slab between z = 0.25 and z = 0.75, outward normals opposite: rank 1. E is least on the
  // plane z = mean of the crossings' z, which holds the mass point, so x is the mass point.
  // Solving about the origin instead would return (0, 0, 0.55).
  const std::vector<EdgeCrossing> crossings{{{0.1, 0.2, 0.25}, {0, 0, -1}},
                                            {{0.9, 0.3, 0.25}, {0, 0, -1}},
                                            {{0.2, 0.8, 0.75}, {0, 0, 1}},
                                            {{0.6, 0.9, 0.75}, {0, 0, 1}},
                                            {{0.7, 0.1, 0.75}, {0, 0, 1}}};
  const QefVertex x = solve_qef(crossings, kUnitNode);
  EXPECT_EQ(x.rank, 1);
  EXPECT_FALSE(x.fell_back);
  EXPECT_LT((x.point - Vec3(0.5, 0.46, 0.55)).norm(), 1e-12);
}

TEST(Qef, SinglePlaneGivesTheMassPointOnIt) {
  const Vec3 n = Vec3(1, 2, 2) / 3.0, c(0.5, 0.5, 0.5);
  const Vec3 u = Vec3(2, -1, 0).normalized(), v = n.cross(u);
  std::vector<EdgeCrossing> crossings;
  for (const auto& [a, b] : {std::pair{0.3, 0.1}, {-0.2, 0.25}, {0.05, -0.3}, {0.4, 0.4}})
    crossings.push_back({c + a * u + b * v, n});
  const QefVertex x = solve_qef(crossings, kUnitNode);
  EXPECT_EQ(x.rank, 1);
  EXPECT_FALSE(x.fell_back);
  EXPECT_LT((x.point - mass_point(crossings)).norm(), 1e-12);
  EXPECT_NEAR(n.dot(x.point - c), 0.0, 1e-12);
}

TEST(Qef, NearlyParallelPlanesAreTruncatedToRankOne) {
  // Planes 5° apart (below the cut-off's 11.4°) that meet at x ≈ 1.03, outside the node. The
  // singular vector dropped is along n1 − n2; x moves from the mass point along n1 + n2 only,
  // by the least-squares step t = Σ (nᵢ·v)(nᵢ·(pᵢ − m)) / Σ (nᵢ·v)².
  const double tilt = 5.0 * std::numbers::pi / 180.0;
  const Vec3 n1(0, 0, 1), n2(std::sin(tilt), 0, std::cos(tilt));
  const std::vector<EdgeCrossing> crossings{{{0.2, 0.5, 0.5}, n1}, {{0.8, 0.5, 0.52}, n2}};
  const Vec3 m = mass_point(crossings), v = (n1 + n2).normalized();
  double numerator = 0.0, denominator = 0.0;
  for (const EdgeCrossing& c : crossings) {
    numerator += c.normal.dot(v) * c.normal.dot(c.point - m);
    denominator += c.normal.dot(v) * c.normal.dot(v);
  }
  const QefVertex x = solve_qef(crossings, kUnitNode);
  EXPECT_EQ(x.rank, 1);
  EXPECT_FALSE(x.fell_back);
  EXPECT_LT((x.point - (m + numerator / denominator * v)).norm(), 1e-12);
}

TEST(Qef, MinimiserOutsideTheNodeFallsBackToTheMassPoint) {
  // z = 0.5 and x + z = 1.8 meet along x = 1.3, z = 0.5: outside the unit node.
  const Vec3 slanted = Vec3(1, 0, 1).normalized();
  const std::vector<EdgeCrossing> crossings{{{0.1, 0.5, 0.5}, {0, 0, 1}},
                                            {{0.3, 0.5, 0.5}, {0, 0, 1}},
                                            {{0.9, 0.2, 0.9}, slanted},
                                            {{0.95, 0.8, 0.85}, slanted}};
  const QefVertex x = solve_qef(crossings, kUnitNode);
  EXPECT_EQ(x.rank, 2);
  EXPECT_TRUE(x.fell_back);
  EXPECT_LT((x.point - mass_point(crossings)).norm(), 1e-15);
  EXPECT_TRUE(kUnitNode.contains(x.point));
}

TEST(Qef, CornerOnTheNodesFaceStaysInside) {
  // Three planes meeting at (1, 0.5, 0.5) on the node's face x = 1, normals not along the axes
  // so that round-off may put the minimiser just outside: within the tolerance it is kept.
  const Vec3 corner(1, 0.5, 0.5);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Vec3(3, -1, 2).normalized()).toRotationMatrix();
  std::vector<EdgeCrossing> crossings;
  for (int axis = 0; axis < 3; ++axis)
    crossings.push_back({corner - 0.1 * r.col((axis + 1) % 3), r.col(axis)});
  const QefVertex x = solve_qef(crossings, kUnitNode);
  EXPECT_EQ(x.rank, 3);
  EXPECT_FALSE(x.fell_back);
  EXPECT_LT((x.point - corner).norm(), 1e-12);
}

TEST(Qef, NoCrossingsIsAnError) {
  EXPECT_THROW(solve_qef(std::vector<EdgeCrossing>{}, kUnitNode), std::invalid_argument);
}

}  // namespace
}  // namespace volmesh
