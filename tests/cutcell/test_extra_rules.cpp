// The extra refinement rules run between grid passes on the leaves a split touched
// (split_by_extra_rules) must split exactly what repeated grid passes split.
#include <gtest/gtest.h>

#include <optional>

#include "cut_grid.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/surface.hpp"
#include "../domain/test_surface_domain_support.hpp"

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
      split_by_extra_rules(by_rounds, *domain, grid.vertices, memo, std::move(first), max_level, clearance).rounds;
  EXPECT_EQ(rounds, passes);
  EXPECT_TRUE(grid_selection(by_rounds, *domain, max_level, clearance, grid, memo).empty());
  ASSERT_EQ(by_rounds.num_leaves(), by_grid.num_leaves());
  for (Index i = 0; i < by_grid.num_leaves(); ++i) {
    ASSERT_EQ(by_rounds.leaf(i).anchor, by_grid.leaf(i).anchor) << i;
    ASSERT_EQ(by_rounds.leaf(i).level, by_grid.leaf(i).level) << i;
  }
}

// refined_grid tests the rules after a split only on the leaves the split made or touched:
// on every later grid they must select what they select among all leaves. Returns how many
// later grids select any leaf.
int later_selections(const Domain& domain, int level) {
  const CutcellOptions options;
  OctreeOptions octree;
  octree.level = level;
  const int max_level = octree.level + options.crossing_levels;
  const double clearance = options.vertex_clearance, theta = options.feature_theta;
  GridSettings settings;
  settings.exact = settings.face.exact_points = settings.cell.exact_points = true;
  Octree tree = build_octree(domain, octree);
  const auto rules = [&](const Grid& grid, const LeafMask& among) {
    std::vector<Index> out = leaves_crossed_twice(grid, max_level, among);
    for (const std::vector<Index>& more : {leaves_thin_at_face_centres(grid, max_level, clearance, among),
                                           leaves_hiding_features(grid, max_level, theta, among)})
      out.insert(out.end(), more.begin(), more.end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };
  Grid grid;
  EdgeMemo memo;
  std::optional<std::vector<OctreeLeaf>> touched;
  int selections = 0;
  for (int pass = 0; pass < 10; ++pass) {
    grid = make_grid(tree, domain, settings, grid.vertices);
    find_edge_points(grid, memo);
    std::vector<Index> all = rules(grid, {});
    if (touched) {
      EXPECT_EQ(rules(grid, leaves_among(tree, *touched)), all) << "level " << level << ", pass " << pass;
      selections += !all.empty();
    }
    if (all.empty()) break;
    touched = split_by_extra_rules(tree, domain, grid.vertices, memo, std::move(all), max_level, clearance).touched;
  }
  return selections;
}

// On fandisk at level 6 the second grid's hidden-feature rule, which the local rounds do not
// apply, selects leaves (a ridge the first splits uncovered); on builtin:primitives at level 5
// no later grid selects any.
TEST(ExtraRules, RulesSelectOnlyAmongTheLeavesASplitTouched) {
  EXPECT_EQ(later_selections(*make_builtin_domain("primitives"), 5), 0);
  auto surface = surface_test::cgal_mesh("fandisk.off");
  if (!surface) GTEST_SKIP() << "libcgal-demo is not installed";
  const SurfaceDomain domain({{std::move(*surface), 0, "fandisk.off"}});
  EXPECT_GE(later_selections(domain, 6), 1);
}

}  // namespace
}  // namespace volmesh::cutcell
