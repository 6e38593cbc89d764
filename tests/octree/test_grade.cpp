// Buffer layers between levels (grade): checked on the leaf boxes pairwise.
#include <gtest/gtest.h>

#include "brute_force.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"

namespace volmesh {
namespace {

// Distance between two leaf boxes along the axis where they are farthest apart (the buffer
// grows each level's region by whole cells in x, y and z).
std::int64_t box_gap(const OctreeLeaf& a, const OctreeLeaf& b) {
  std::int64_t gap = 0;
  for (int k = 0; k < 3; ++k) {
    const std::int64_t lo = std::max<std::int64_t>(a.anchor[k], b.anchor[k]);
    const std::int64_t hi = std::min<std::int64_t>(a.anchor[k] + a.size(), b.anchor[k] + b.size());
    gap = std::max(gap, lo - hi);
  }
  return gap;
}

// Pairs of leaves two or more levels apart that lie closer than `cells` - 1 cells of the
// level between them.
int thin_transitions(const Octree& tree, int cells) {
  std::vector<OctreeLeaf> coarse_ones;  // those with a level two finer in the tree
  for (const OctreeLeaf& l : tree.leaves())
    if (l.level + 2 <= tree.max_leaf_level()) coarse_ones.push_back(l);
  int count = 0;
  for (const OctreeLeaf& fine : tree.leaves())
    for (const OctreeLeaf& coarse : coarse_ones)
      if (fine.level >= coarse.level + 2 &&
          box_gap(fine, coarse) < std::int64_t{cells - 1} * (kOctreeGrid >> (coarse.level + 1)))
        ++count;
  return count;
}

TEST(Grade, EachLevelSpansTheGivenCellsBeforeTheNextCoarserOne) {
  const auto domain = make_builtin_domain("ball");
  OctreeOptions options;
  options.level = 5;
  options.base_level = 1;
  const Octree balanced = build_octree(*domain, options);
  ASSERT_GT(thin_transitions(balanced, 3), 0);
  for (const int cells : {2, 3, 4}) {
    options.cells_between_levels = cells;
    const Octree graded = build_octree(*domain, options);
    EXPECT_EQ(thin_transitions(graded, cells), 0) << cells << " cells";
    EXPECT_EQ(test::sampled_balance_violations(graded), 0);
    EXPECT_EQ(graded.max_leaf_level(), 5);
    // Refinement only: every leaf lies in a leaf of the balanced tree at most as fine.
    for (const OctreeLeaf& l : graded.leaves())
      EXPECT_LE(balanced.leaf(balanced.leaf_containing(l.anchor)).level, l.level);
    EXPECT_GT(graded.num_leaves(), balanced.num_leaves());
  }
}

TEST(Grade, OneCellIsTheBalanceAloneAndLessIsAnError) {
  const auto domain = make_builtin_domain("ball");
  OctreeOptions options;
  options.level = 4;
  const Octree balanced = build_octree(*domain, options);
  Octree same = balanced;
  grade(same, 1);
  ASSERT_EQ(same.num_leaves(), balanced.num_leaves());
  for (Index i = 0; i < same.num_leaves(); ++i) {
    EXPECT_EQ(same.leaf(i).anchor, balanced.leaf(i).anchor);
    EXPECT_EQ(same.leaf(i).level, balanced.leaf(i).level);
  }
  EXPECT_THROW(grade(same, 0), InputError);
}

}  // namespace
}  // namespace volmesh
