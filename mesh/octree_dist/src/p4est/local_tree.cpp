#include "local_tree.hpp"

#include <algorithm>
#include <cmath>

namespace volmesh::octree_dist {
namespace {

std::uint64_t curve_length(const OctreeLeaf& leaf) {
  const std::uint64_t s = leaf.size();
  return s * s * s;
}

// The Morton curve's stretch [from, to) as the largest aligned nodes, in order.
void fill(std::uint64_t from, std::uint64_t to, int part, LocalTree& out) {
  while (from < to) {
    int k = kOctreeMaxLevel;  // a node of edge 2^k spans 8^k codes
    while (k > 0 && ((from & ((std::uint64_t{1} << 3 * k) - 1)) != 0 || from + (std::uint64_t{1} << 3 * k) > to)) --k;
    out.leaves.push_back({morton_decode(from), kOctreeMaxLevel - k});
    out.part.push_back(part);
    from += std::uint64_t{1} << 3 * k;
  }
}

}  // namespace

LocalTree local_tree(const DistributedOctree& tree) {
  LocalTree out;
  std::uint64_t next = 0;  // where the curve is covered up to
  const auto add = [&](const OctreeLeaf& leaf, int part) {
    const std::uint64_t first = morton_encode(leaf.anchor);
    fill(next, first, tree.ranks, out);
    out.leaves.push_back(leaf);
    out.part.push_back(part);
    next = first + curve_length(leaf);
  };
  std::size_t g = 0;
  for (const OctreeLeaf& leaf : tree.leaves) {
    for (; g < tree.ghosts.size() && morton_encode(tree.ghosts[g].anchor) < morton_encode(leaf.anchor); ++g)
      add(tree.ghosts[g], tree.ghost_owner[g]);
    add(leaf, tree.rank);
  }
  for (; g < tree.ghosts.size(); ++g) add(tree.ghosts[g], tree.ghost_owner[g]);
  fill(next, std::uint64_t{1} << 3 * kOctreeMaxLevel, tree.ranks, out);
  return out;
}

std::uint64_t cell_code(const Octree& tree, const Vec3& x) {
  const double unit = tree.root_size() / kOctreeGrid;
  GridPoint p;
  for (int a = 0; a < 3; ++a) {
    const double g = std::floor((x[a] - tree.origin()[a]) / unit);
    p[a] = static_cast<std::uint32_t>(std::clamp(g, 0.0, static_cast<double>(kOctreeGrid - 1)));
  }
  return morton_encode(p);
}

}  // namespace volmesh::octree_dist
