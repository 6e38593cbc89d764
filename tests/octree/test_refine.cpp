// Balance, the refinement fixpoint, the interface criterion and the octree limits.
#include <gtest/gtest.h>

#include "brute_force.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/analytic.hpp"
#include "volmesh/domain/builtin.hpp"

namespace volmesh {
namespace {

TEST(Balance, RandomTreesBecomeBalancedByRefinementOnly) {
  for (unsigned seed = 10; seed < 13; ++seed) {
    const Octree original = test::random_tree(seed, 5, 0.25, 7);
    Octree tree = original;
    ASSERT_GT(test::unbalanced_pairs(original), 0) << "seed " << seed;
    balance(tree);
    EXPECT_EQ(test::unbalanced_pairs(tree), 0) << "seed " << seed;
    EXPECT_EQ(test::sampled_balance_violations(tree), 0);
    // Only refines: each new leaf lies inside an original leaf of at most its level.
    for (const OctreeLeaf& l : tree.leaves())
      EXPECT_LE(original.leaf(original.leaf_containing(l.anchor)).level, l.level);
    // Idempotent.
    const Octree again = [&] {
      Octree t = tree;
      balance(t);
      return t;
    }();
    ASSERT_EQ(again.num_leaves(), tree.num_leaves());
  }
}

TEST(Balance, EdgeContactAloneForcesRefinement) {
  // Two leaves that touch only along an edge: a level-3 leaf at the centre's corner and the
  // diagonal level-1 octant. Face balance alone would not split the octant.
  Octree tree(Vec3::Zero(), 1.0);
  tree.split(std::vector<Index>{0});
  for (int level = 1; level < 3; ++level)
    tree.split(std::vector<Index>{tree.leaf_containing({kOctreeGrid / 2 - 1, kOctreeGrid / 2 - 1, 0})});
  ASSERT_GT(test::unbalanced_pairs(tree), 0);
  balance(tree);
  EXPECT_EQ(test::unbalanced_pairs(tree), 0);
  // The octant diagonal across the z edge through the centre is split.
  EXPECT_EQ(tree.find_leaf({kOctreeGrid / 2, kOctreeGrid / 2, 0}, 1), kNoIndex);
}

TEST(Refine, PredicateFixpointReachesTheMaximumLevelAndStaysBalanced) {
  Octree tree(Vec3::Zero(), 2.0);
  const Vec3 target(0.3, 1.7, 0.9);
  const int passes = refine(
      tree,
      [&](const Octree& t, Index i) {
        const OctreeLeaf& l = t.leaf(i);
        const Vec3 lo = t.world(l.anchor), hi = t.world(l.corner(7));
        return (lo.array() <= target.array()).all() && (target.array() < hi.array()).all();
      },
      8);
  EXPECT_EQ(passes, 8);
  const GridPoint p{static_cast<std::uint32_t>(0.15 * kOctreeGrid),
                    static_cast<std::uint32_t>(0.85 * kOctreeGrid),
                    static_cast<std::uint32_t>(0.45 * kOctreeGrid)};
  EXPECT_EQ(tree.leaf(tree.leaf_containing(p)).level, 8);
  EXPECT_EQ(test::sampled_balance_violations(tree), 0);
  EXPECT_EQ(tree.max_leaf_level(), 8);
}

TEST(Refine, PredicateMaySeeNeighbours) {
  // "Split a leaf with a finer face neighbour" spreads refinement to a uniform tree.
  Octree tree(Vec3::Zero(), 1.0);
  tree.split(std::vector<Index>{0});
  tree.split(std::vector<Index>{0});
  refine(
      tree,
      [](const Octree& t, Index i) {
        for (int f = 0; f < 6; ++f)
          if (t.face_neighbours(i, f).kind == FaceKind::Finer) return true;
        return false;
      },
      2);
  EXPECT_EQ(tree.num_leaves(), 64);
}

TEST(Refine, InterfaceLeavesReachTheLevelAndNoCoarserLeafIsCut) {
  const auto domain = make_builtin_domain("primitives");
  OctreeOptions options;
  options.level = 5;
  const Octree tree = build_octree(*domain, options);
  EXPECT_EQ(tree.max_leaf_level(), 5);
  EXPECT_EQ(test::sampled_balance_violations(tree), 0);
  int cut = 0;
  for (const OctreeLeaf& l : tree.leaves()) {
    bool differs = false, crossed = false;
    const Index r0 = domain->region(tree.world(l.corner(0)));
    for (int k = 1; k < 8; ++k) differs = differs || domain->region(tree.world(l.corner(k))) != r0;
    for (const auto& e : kEdgeCorners)
      crossed = crossed ||
                !domain->crossings(tree.world(l.corner(e[0])), tree.world(l.corner(e[1]))).empty();
    if (differs || crossed) {
      EXPECT_EQ(l.level, 5);
      ++cut;
    }
  }
  EXPECT_GT(cut, 1000);
}

TEST(Refine, EdgeCrossedTwiceWithEqualEndsIsRefined) {
  // A slab thinner than the base cells lies between grid planes: no corner is inside, but
  // edges cross it twice.
  const AnalyticDomain slab({box(Vec3(0.0, 0.0, 0.40), Vec3(1.0, 1.0, 0.43))}, {0, 1});
  OctreeOptions options;
  options.level = 6;
  options.base_level = 2;
  const Octree tree = build_octree(slab, options);
  EXPECT_EQ(tree.max_leaf_level(), 6);
  const Index at_slab = tree.leaf_containing(
      {kOctreeGrid / 2, kOctreeGrid / 2,
       static_cast<std::uint32_t>((0.415 - tree.origin().z()) / tree.root_size() * kOctreeGrid)});
  EXPECT_EQ(tree.leaf(at_slab).level, 6);
}

TEST(Refine, BoxFrontRefinesItsRegion) {
  const auto domain = make_builtin_domain("ball");
  OctreeOptions options;
  options.level = 3;
  options.boxes.push_back({Box3{Vec3(-0.2, -0.2, -0.2), Vec3(0.2, 0.2, 0.2)}, 6});
  const Octree tree = build_octree(*domain, options);
  const Index centre = tree.leaf_containing({kOctreeGrid / 2, kOctreeGrid / 2, kOctreeGrid / 2});
  EXPECT_EQ(tree.leaf(centre).level, 6);
  EXPECT_EQ(tree.max_leaf_level(), 6);
  EXPECT_EQ(test::sampled_balance_violations(tree), 0);
}

TEST(Refine, SurfaceFrontRefinesTowardItsInterfaces) {
  const auto domain = make_builtin_domain("ball");
  const AnalyticDomain front({sphere(Vec3::Zero(), 0.5)}, {0, 1});
  OctreeOptions options;
  options.level = 3;
  options.surfaces.push_back({&front, 5});
  const Octree tree = build_octree(*domain, options);
  const double h5 = tree.cell_size(5);
  int fine = 0;
  for (const OctreeLeaf& l : tree.leaves())
    if (l.level == 5) {
      ++fine;
      const double r = (tree.world(l.centre())).norm();
      EXPECT_NEAR(r, 0.5, 2.0 * std::sqrt(3.0) * h5);  // a child of a level-4 leaf cut by it
    }
  EXPECT_GT(fine, 100);
}

// A layered model fills its box: the root starts at the box (all six faces are the root's
// for the unit cube, and no leaf is cut by them); other domains get the 5% margin all round,
// and a margin that is set is kept.
TEST(Refine, RootOfADomainFillingItsBoxIsTheBox) {
  const auto layers = make_builtin_domain("layers6");
  ASSERT_TRUE(layers->fills_bounds());
  OctreeOptions options;
  options.level = 2;
  const Octree tree = build_octree(*layers, options);
  EXPECT_EQ(tree.world({0, 0, 0}), Vec3::Zero());
  EXPECT_EQ(tree.cell_size(0), 1.0);

  options.margin = 0.05;
  const RootCube grown = octree_root(*layers, options);
  EXPECT_NEAR(grown.side, 1.1, 1e-15);
  EXPECT_LT((grown.origin - Vec3::Constant(-0.05)).norm(), 1e-15);

  const auto ball = make_builtin_domain("ball");
  ASSERT_FALSE(ball->fills_bounds());
  const RootCube around = octree_root(*ball, OctreeOptions{});
  const Box3 box = ball->bounds();
  EXPECT_NEAR(around.side, 1.1 * box.size().maxCoeff(), 1e-12);
  EXPECT_LT((around.origin + Vec3::Constant(0.5 * around.side) - box.centre()).norm(), 1e-12);

  options.margin = -1.0;
  EXPECT_THROW(octree_root(*layers, options), InputError);
}

TEST(Refine, LimitsAreInputErrors) {
  const auto domain = make_builtin_domain("ball");
  OctreeOptions options;
  options.level = 25;
  try {
    build_octree(*domain, options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--level 25 exceeds the maximum 20");
  }
  options.level = 0;
  EXPECT_THROW(build_octree(*domain, options), InputError);
  options.level = -1;
  EXPECT_THROW(build_octree(*domain, options), InputError);
  Octree tree(Vec3::Zero(), 1.0);
  EXPECT_THROW(refine(tree, [](const Octree&, Index) { return true; }, 21), InputError);
}

}  // namespace
}  // namespace volmesh
