// The extra refinement rules: what they select (extra_rules.hpp), that the refinement leaves
// no leaf they would select, and that after a split only the leaves it touched can change
// their verdict (what the local rounds between grid passes rely on).
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "cut_grid.hpp"
#include "extra_rules.hpp"
#include "volmesh/domain/analytic.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/surface.hpp"
#include "../domain/test_surface_domain_support.hpp"

namespace volmesh::cutcell {
namespace {

// On plain candidates: a leaf with an edge crossed twice is selected whatever the
// clearance; a transition face's centre counts the interface ahead of it into the leaf
// (along +x from face 0, along -x from face 1), within the clearance times the leaf's edge.
TEST(ExtraRules, SelectEdgesCrossedTwiceAndInterfacesNearFaceCentres) {
  const AnalyticDomain unit_ball({sphere(Vec3::Zero(), 1.0)}, {0, 1});
  RuleCandidates c;
  c.add_leaf(10, 1);
  c.add_leaf(11, 2);
  c.add_leaf(12, 0);
  c.add_transition_face(0, Vec3(0.95, 0, 0), 1.0);  // the sphere 0.05 ahead
  c.add_leaf(13, 0);
  c.add_transition_face(1, Vec3(1.2, 0, 0), 2.0);  // 0.2 ahead, the leaf's edge 2: 0.1 of it
  c.add_leaf(14, 0);
  c.add_transition_face(1, Vec3(0.95, 0, 0), 1.0);  // the sphere 0.05 behind, outside the leaf
  EXPECT_EQ(leaves_selected(c, unit_ball, 0.0), (std::vector<Index>{11}));
  EXPECT_EQ(leaves_selected(c, unit_ball, 0.04), (std::vector<Index>{11}));
  EXPECT_EQ(leaves_selected(c, unit_ball, 0.06), (std::vector<Index>{11, 12}));
  EXPECT_EQ(leaves_selected(c, unit_ball, 0.11), (std::vector<Index>{11, 12, 13}));
}

// What the first two rules would select on a grid of the tree, counted straight from the
// domain, one query per whole leaf edge and per transition face, apart from the grid's
// edge tables and the rules' own gathering.
struct Selected {
  Index crossed_twice = 0;  // cut leaves below max_level with an edge crossed more than once
  Index thin = 0;           // ... with an interface within clearance of a face centre
};
Selected selected_by_domain(const Octree& tree, const Domain& domain, int max_level, double clearance) {
  const Grid grid = make_grid(tree, domain, GridSettings{});
  const OctreeVertices& v = grid.vertices;
  const auto first_transversal = [](const std::vector<Crossing>& hits) {
    return std::find_if(hits.begin(), hits.end(), [](const Crossing& c) { return c.before != c.after; });
  };
  Selected out;
  for (Index i = 0; i < tree.num_leaves(); ++i) {
    if (!grid.cut[i] || tree.leaf(i).level >= max_level) continue;
    bool twice = false, thin = false;
    for (int e = 0; e < 12; ++e) {
      const std::vector<Crossing> hits = domain.crossings(v.points[v.leaf_corners[i][kEdgeCorners[e][0]]],
                                                          v.points[v.leaf_corners[i][kEdgeCorners[e][1]]]);
      twice = twice || std::count_if(hits.begin(), hits.end(), [](const Crossing& c) { return c.before != c.after; }) > 1;
    }
    for (int f = 0; f < 6; ++f) {
      const Index centre = v.leaf_face_centre[i][f];
      if (centre == kNoIndex) continue;
      const Vec3 inward = (f & 1 ? -1.0 : 1.0) * grid.leaf_size(i) * Vec3::Unit(f / 2);
      const std::vector<Crossing> hits = domain.crossings(v.points[centre], v.points[centre] + inward);
      const auto c = first_transversal(hits);
      thin = thin || (c != hits.end() && c->t < clearance);
    }
    out.crossed_twice += twice;
    out.thin += thin;
  }
  return out;
}

// builtin:primitives at level 5: its octree has leaf edges crossed twice beside the junction
// lines and corners, and the splits they call for make transition faces with interfaces
// near their centres (left so without the clearance rule); the refinement leaves no leaf
// below the deepest level of the rules that either rule selects.
TEST(ExtraRules, RefinementLeavesNoLeafTheRulesSelect) {
  const auto domain = make_builtin_domain("primitives");
  CutcellOptions options;
  options.octree.level = 5;
  const int max_level = options.octree.level + options.crossing_levels;
  const double clearance = options.vertex_clearance;
  Octree tree = build_octree(*domain, options.octree);
  EXPECT_GT(selected_by_domain(tree, *domain, max_level, clearance).crossed_twice, 0);

  CutcellStats stats;
  CutcellOptions without_clearance = options;
  without_clearance.vertex_clearance = 0.0;
  Octree crossings_only = tree;
  refined_grid(crossings_only, *domain, without_clearance, stats);
  EXPECT_GT(selected_by_domain(crossings_only, *domain, max_level, clearance).thin, 0);

  refined_grid(tree, *domain, options, stats);
  EXPECT_EQ(tree.max_leaf_level(), max_level);
  const Selected after = selected_by_domain(tree, *domain, max_level, clearance);
  EXPECT_EQ(after.crossed_twice, 0);
  EXPECT_EQ(after.thin, 0);
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
    std::vector<Index> out = leaves_by_extra_rules(grid, max_level, clearance, among);
    const std::vector<Index> hiding = leaves_hiding_features(grid, max_level, theta, among);
    out.insert(out.end(), hiding.begin(), hiding.end());
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
