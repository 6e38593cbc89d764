// The untangling (optimise.hpp) where a fold cannot open: its rounds end once they stop getting
// anywhere, the mesh is given back still folded (and so refused), not after the whole budget.
#include <gtest/gtest.h>

#include "hex_checks.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/hexdc/optimise.hpp"

namespace volmesh {
namespace {

using test_hexdc::invalid_hexes;

constexpr Index kCells = 4;  // per axis of the grid
constexpr double kSide = 1.0 / kCells;

TEST(OptimiseStuckFold, GivenUpBeforeTheRoundsRunOut) {
  HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {kCells, kCells, kCells});
  // The box's corner node pushed through its three neighbours: without a surface every boundary
  // node is held, so the corner tet there stays inverted whatever the free nodes do.
  mesh.points[0] = Vec3::Constant(1.5 * kSide);
  ASSERT_GT(invalid_hexes(mesh), 0);
  const OptimiseOptions options;
  const OptimiseStats stats = optimise_hexes(mesh, {}, options);
  EXPECT_GT(stats.invalid_tets_after, 0);
  EXPECT_GT(invalid_hexes(mesh), 0);
  // Both attempts (the second after the features' release) end early.
  EXPECT_GT(stats.untangle_rounds, 1);
  EXPECT_LT(stats.untangle_rounds, options.untangle_rounds);
}

}  // namespace
}  // namespace volmesh
