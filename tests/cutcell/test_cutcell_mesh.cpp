#include <gtest/gtest.h>

#include <array>

#include "volmesh/core/validity.hpp"
#include "volmesh/cutcell/cutcell.hpp"
#include "volmesh/domain/builtin.hpp"

namespace volmesh {
namespace {

TEST(CutcellMesh, BallIsValid) {
  const auto domain = make_builtin_domain("ball");
  for (int level = 2; level <= 5; ++level) {
    CutcellOptions options;
    options.octree.level = level;
    CutcellStats stats;
    const PolyMesh mesh = cutcell_mesh(*domain, options, &stats);
    const ValidityReport report = check_validity(mesh);
    std::cout << "level " << level << " cells " << stats.cells << " cut " << stats.cut_cells
              << " volume " << report.total_volume << " err " << report.total_volume - 4.0 / 3.0 * M_PI
              << " moved " << stats.moved_vertices << " unresolved " << stats.unresolved_vertices
              << " minvol " << stats.min_cell_volume_ratio << " t " << stats.total_seconds << "\n";
    for (const auto& p : report.problems) std::cout << "  " << p << "\n";
    EXPECT_TRUE(report.valid());
  }
}

// builtin:layers6: the unit box's faces, edges and corners are the boundary with region 0
// and lie inside octree cells. Every mesh point on the box lies on its planes: edge points
// take the box crossing, junction points are fitted to the box's planes first and moved
// back onto them after clamping into the cell. So the regions fill the box to rounding (no
// gap, no overlap); before, they added up to 1 - 6.9e-5 (level 3) and 1 - 4.1e-8 (level 4).
TEST(CutcellMesh, Layers6RegionsFillTheUnitBox) {
  const auto domain = make_builtin_domain("layers6");
  for (int level = 3; level <= 4; ++level) {
    CutcellOptions options;
    options.octree.level = level;
    const ValidityReport report = check_validity(cutcell_mesh(*domain, options));
    ASSERT_TRUE(report.valid()) << "level " << level;
    EXPECT_NEAR(report.total_volume, 1.0, 1e-10) << "level " << level;
  }
}

}  // namespace
}  // namespace volmesh
