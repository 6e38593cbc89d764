// The distributed octree against the serial one (run under mpirun -np 1, 2 and 4): the
// ranks' leaves, in rank order, are build_octree's leaves in Morton order; the ghost layer
// is every other rank's leaf touching one's own; the partition balances the weights.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "gather.hpp"
#include "octree_case.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/octree_dist/distributed_octree.hpp"

namespace volmesh {
namespace {

// Every rank's values, concatenated in rank order, on every rank; and each value's rank.
struct Gathered {
  std::vector<std::uint64_t> values;
  std::vector<int> rank;
};
Gathered gather(const std::vector<std::uint64_t>& mine) {
  Gathered g;
  g.values = test::gather_to_all(mine, MPI_UINT64_T, &g.rank);
  return g;
}

std::vector<std::uint64_t> codes(const std::vector<OctreeLeaf>& leaves) {
  std::vector<std::uint64_t> out;
  for (const OctreeLeaf& l : leaves) out.push_back(octree_code(l.anchor, l.level));
  return out;
}

std::unique_ptr<Domain> domain_or_null(const std::string& spec) {
  if (spec.starts_with("builtin:") || std::filesystem::exists(spec)) return open_domain(spec);
  return nullptr;
}

using test::Case;
using test::options_of;

// The gathered leaves equal the serial tree's, leaf for leaf in Morton order.
void expect_serial_leaves(const DistributedOctree& tree, const Octree& serial, const std::string& what) {
  const Gathered all = gather(codes(tree.leaves));
  const std::vector<std::uint64_t> expected = codes({serial.leaves().begin(), serial.leaves().end()});
  ASSERT_EQ(all.values.size(), expected.size()) << what;
  EXPECT_EQ(tree.global_leaves, serial.num_leaves()) << what;
  const auto [a, b] = std::mismatch(all.values.begin(), all.values.end(), expected.begin());
  EXPECT_TRUE(a == all.values.end()) << what << ": first difference at leaf " << (a - all.values.begin());
}

TEST(DistributedOctree, SameLeavesAsTheSerialOctree) {
  const std::vector<Case> cases{
      {"builtin:ball", 5, 3, 1},          {"builtin:ball", 6, 2, 3},
      {"builtin:ball", 3, 0, 2},  // one leaf to start with: ranks without leaves
      {"builtin:primitives", 5, 3, 1},    {"builtin:primitives", 5, 3, 2},
      {"builtin:cube-inclusion", 5, 2, 1}, {"builtin:cube-inclusion", 4, 1, 4},
      {std::string(VOLMESH_CGAL_DATA) + "/meshes/elephant.off", 5, 3, 2},
  };
  int compared = 0;
  for (const Case& c : cases) {
    const std::unique_ptr<Domain> domain = domain_or_null(c.domain);
    if (!domain) continue;
    const std::string what = c.domain + " level " + std::to_string(c.level) + " base " +
                             std::to_string(c.base_level) + " cells between levels " +
                             std::to_string(c.cells_between_levels);
    const OctreeOptions options = options_of(c);
    const DistributedOctree tree = build_distributed_octree(*domain, options);
    expect_serial_leaves(tree, build_octree(*domain, options), what);
    ++compared;
  }
  EXPECT_GE(compared, 7);
}

TEST(DistributedOctree, FrontsAsTheSerialOctree) {
  const std::unique_ptr<Domain> ball = open_domain("builtin:ball");
  const std::unique_ptr<Domain> primitives = open_domain("builtin:primitives");
  OctreeOptions options = options_of({"", 4, 2, 4});
  options.boxes.push_back({{Vec3(-0.3, -0.1, 0.2), Vec3(0.4, 0.5, 0.45)}, 6});
  options.surfaces.push_back({primitives.get(), 5});
  const DistributedOctree tree = build_distributed_octree(*ball, options);
  expect_serial_leaves(tree, build_octree(*ball, options), "ball with a box and a surface front");
}

bool touch(const OctreeLeaf& a, const OctreeLeaf& b) {
  for (int k = 0; k < 3; ++k)
    if (std::int64_t{a.anchor[k]} > std::int64_t{b.anchor[k]} + b.size() ||
        std::int64_t{b.anchor[k]} > std::int64_t{a.anchor[k]} + a.size())
      return false;
  return true;
}

TEST(DistributedOctree, GhostsAreTheOtherRanksLeavesTouchingOnes) {
  for (const char* spec : {"builtin:ball", "builtin:primitives"}) {
    const std::unique_ptr<Domain> domain = open_domain(spec);
    const DistributedOctree tree = build_distributed_octree(*domain, options_of({"", 4, 2, 1}));
    const Gathered all = gather(codes(tree.leaves));
    const Octree serial = build_octree(*domain, options_of({"", 4, 2, 1}));
    ASSERT_EQ(all.values.size(), static_cast<std::size_t>(serial.num_leaves())) << spec;
    std::vector<std::uint64_t> expected;
    std::vector<int> expected_owner;
    for (std::size_t j = 0; j < all.values.size(); ++j) {
      if (all.rank[j] == tree.rank) continue;
      const OctreeLeaf& other = serial.leaf(static_cast<Index>(j));
      if (std::any_of(tree.leaves.begin(), tree.leaves.end(), [&](const OctreeLeaf& l) { return touch(l, other); })) {
        expected.push_back(all.values[j]);
        expected_owner.push_back(all.rank[j]);
      }
    }
    EXPECT_EQ(codes(tree.ghosts), expected) << spec << " rank " << tree.rank;
    EXPECT_EQ(tree.ghost_owner, expected_owner) << spec << " rank " << tree.rank;
    if (tree.ranks > 1) {
      EXPECT_FALSE(tree.ghosts.empty()) << spec;
    }
  }
}

TEST(DistributedOctree, PartitionBalancesCutLeavesWeights) {
  const std::unique_ptr<Domain> domain = open_domain("builtin:primitives");
  const DistributedOctree tree = build_distributed_octree(*domain, options_of({"", 5, 3, 1}));
  ASSERT_EQ(tree.cut.size(), tree.leaves.size());
  std::uint64_t weight = 0;
  for (const std::uint8_t c : tree.cut) weight += c ? kCutLeafWeight : 1;
  const Gathered weights = gather({weight});
  std::uint64_t total = 0;
  for (const std::uint64_t w : weights.values) total += w;
  const double share = static_cast<double>(total) / tree.ranks;
  for (const std::uint64_t w : weights.values) EXPECT_LE(std::abs(static_cast<double>(w) - share), kCutLeafWeight);
  const Gathered cut = gather({static_cast<std::uint64_t>(std::count(tree.cut.begin(), tree.cut.end(), 1))});
  EXPECT_GT(cut.values[0] + cut.values.back(), 0u);
}

TEST(DistributedOctree, SameLeavesOnEveryRun) {
  const std::unique_ptr<Domain> domain = open_domain("builtin:primitives");
  const OctreeOptions options = options_of({"", 5, 3, 2});
  const DistributedOctree a = build_distributed_octree(*domain, options);
  const DistributedOctree b = build_distributed_octree(*domain, options);
  EXPECT_EQ(codes(a.leaves), codes(b.leaves));
  EXPECT_EQ(a.cut, b.cut);
  EXPECT_EQ(codes(a.ghosts), codes(b.ghosts));
}

TEST(DistributedOctree, RefusesWhatBuildOctreeRefusesAndLevelsBeyondP4est) {
  const std::unique_ptr<Domain> domain = open_domain("builtin:ball");
  const auto message = [&](const Case& c) -> std::string {
    try {
      build_distributed_octree(*domain, options_of(c));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message({"", 19, 3, 1}).find("--level 19 exceeds the distributed octree's maximum 18"), std::string::npos);
  EXPECT_NE(message({"", 0, 0, 1}).find("--level 0"), std::string::npos);
  EXPECT_NE(message({"", 3, 2, 0}).find("--cells-between-levels must be at least 1"), std::string::npos);
  EXPECT_TRUE(p4est_built());
  EXPECT_NE(distributed_octree_summary().find("p4est 2."), std::string::npos);
}

}  // namespace
}  // namespace volmesh
