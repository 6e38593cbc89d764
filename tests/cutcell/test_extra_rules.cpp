// The extra refinement rules run between grid passes on the leaves a split touched
// (split_by_extra_rules) must split exactly what repeated grid passes split.
#include <gtest/gtest.h>

#include "cut_grid.hpp"
#include "volmesh/domain/builtin.hpp"

namespace volmesh::cutcell {
namespace {

// The two rules on a grid of the tree (refined_grid's first step); the grid's vertices and
// edge memo in `grid` and `memo`.
std::vector<Index> grid_selection(const Octree& tree, const Domain& domain, int max_level, double clearance,
                                  Grid& grid, EdgeMemo& memo) {
  grid = make_grid(tree, domain, GridSettings{});
  find_edge_points(grid, memo);
  std::vector<Index> out = leaves_crossed_twice(grid, max_level);
  const std::vector<Index> thin = leaves_thin_at_face_centres(grid, max_level, clearance);
  out.insert(out.end(), thin.begin(), thin.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// builtin:primitives at level 5: leaf edges crossed twice beside its junction lines and
// corners, and transition faces near interfaces, for five rounds.
TEST(ExtraRules, LocalRoundsSplitWhatGridPassesSplit) {
  const auto domain = make_builtin_domain("primitives");
  const CutcellOptions options;
  OctreeOptions octree;
  octree.level = 5;
  const int max_level = octree.level + options.crossing_levels;
  const double clearance = options.vertex_clearance;
  Octree by_grid = build_octree(*domain, octree);
  Octree by_rounds = by_grid;

  Grid grid;
  EdgeMemo memo;
  int passes = 0;
  for (std::vector<Index> s; !(s = grid_selection(by_grid, *domain, max_level, clearance, grid, memo)).empty();
       ++passes)
    split_balanced(by_grid, std::move(s));
  ASSERT_GE(passes, 3);

  memo = {};
  std::vector<Index> first = grid_selection(by_rounds, *domain, max_level, clearance, grid, memo);
  const int rounds =
      split_by_extra_rules(by_rounds, *domain, grid.vertices, memo, std::move(first), max_level, clearance);
  EXPECT_EQ(rounds, passes);
  EXPECT_TRUE(grid_selection(by_rounds, *domain, max_level, clearance, grid, memo).empty());
  ASSERT_EQ(by_rounds.num_leaves(), by_grid.num_leaves());
  for (Index i = 0; i < by_grid.num_leaves(); ++i) {
    ASSERT_EQ(by_rounds.leaf(i).anchor, by_grid.leaf(i).anchor) << i;
    ASSERT_EQ(by_rounds.leaf(i).level, by_grid.leaf(i).level) << i;
  }
}

}  // namespace
}  // namespace volmesh::cutcell
