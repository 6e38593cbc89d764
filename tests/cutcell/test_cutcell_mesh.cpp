#include <gtest/gtest.h>

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

}  // namespace
}  // namespace volmesh
