// The untangling (optimise.hpp) where two nodes of an edge sit on one point, as the projection
// leaves them where two boundary nodes share a closest point: the collapsed edge's node must not
// hold every other node of the descent still.
#include <gtest/gtest.h>

#include "hex_checks.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/hexdc/optimise.hpp"

namespace volmesh {
namespace {

using test_hexdc::invalid_hexes;

constexpr Index kCells = 4;  // per axis of the grid
constexpr double kSide = 1.0 / kCells;
// How far apart the collapsed edge's nodes are left, in cells: round-off.
constexpr double kCollapsedGap = 1e-15;

std::size_t node(Index i, Index j, Index k) {
  return static_cast<std::size_t>(i + (kCells + 1) * (j + (kCells + 1) * k));
}

TEST(OptimiseCollapsedEdge, FoldsElsewhereStillUntangle) {
  HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {kCells, kCells, kCells});
  // An interior node pushed through its neighbours: its hexes fold.
  mesh.points[node(1, 1, 1)] += Vec3(1.4 * kSide, 1.3 * kSide, 1.2 * kSide);
  // Two other interior nodes of one edge drawn onto one point, to round-off.
  mesh.points[node(2, 3, 3)] = mesh.points[node(3, 3, 3)] + Vec3::Constant(kCollapsedGap * kSide);
  ASSERT_GT(invalid_hexes(mesh), 0);
  const OptimiseStats stats = optimise_hexes(mesh, {});
  EXPECT_GT(stats.invalid_tets_before, 0);
  EXPECT_GT(stats.untangle_iterations, 1);
  EXPECT_EQ(stats.invalid_tets_after, 0);
  EXPECT_EQ(invalid_hexes(mesh), 0);
  // The collapsed edge opens again.
  EXPECT_GT((mesh.points[node(2, 3, 3)] - mesh.points[node(3, 3, 3)]).norm(), 0.1 * kSide);
}

}  // namespace
}  // namespace volmesh
