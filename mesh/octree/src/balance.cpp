// 2:1 balance across faces and edges. Formulation: every internal node P at level k >= 1
// must have its 18 face and edge neighbours of level k as nodes (leaf or internal); then no
// leaf sharing part of a face or an edge with a leaf of level l is coarser than l - 1.
// Those neighbours outside P's parent are children of the parent's three face and three edge
// neighbours on P's side, so the condition reads: these six nodes of level k - 1 are
// internal. A missing one is made so by splitting the leaf that covers it.
#include <algorithm>
#include <vector>

#include "volmesh/octree/octree.hpp"

namespace volmesh {

namespace {

struct Node {
  GridPoint anchor;
  int level;
};

GridPoint align(const GridPoint& p, int level) {
  const std::uint32_t mask = ~((kOctreeGrid >> level) - 1);
  return {p[0] & mask, p[1] & mask, p[2] & mask};
}

// The parent's face and edge neighbours on the node's side (up to six, inside the root).
int uncles(const Node& node, std::array<GridPoint, 6>& out) {
  const int k = node.level - 1;
  const std::int64_t size = kOctreeGrid >> k;
  const GridPoint parent = align(node.anchor, k);
  std::array<std::int64_t, 3> away;  // towards the node's side of the parent
  for (int a = 0; a < 3; ++a) away[a] = node.anchor[a] == parent[a] ? -size : size;
  int count = 0;
  for (int mask = 1; mask < 7; ++mask) {  // the sets of one or two axes
    std::array<std::int64_t, 3> q;
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
      q[a] = parent[a] + ((mask >> a & 1) ? away[a] : 0);
      inside = inside && q[a] >= 0 && q[a] < kOctreeGrid;
    }
    if (inside)
      out[count++] = {static_cast<std::uint32_t>(q[0]), static_cast<std::uint32_t>(q[1]),
                      static_cast<std::uint32_t>(q[2])};
  }
  return count;
}

constexpr Index kInternal = 0, kLeaf = 1;

class Balancer {
 public:
  explicit Balancer(const Octree& tree) : internal_(kOctreeMaxLevel + 1) {
    nodes_.reserve(tree.num_leaves() + tree.num_leaves() / 7 + 1);
    for (const OctreeLeaf& leaf : tree.leaves()) {
      nodes_.insert(octree_code(leaf.anchor, leaf.level), kLeaf);
      leaves_.push_back({leaf.anchor, leaf.level});
      // Ancestors up to the first one already recorded (Morton order shares them).
      for (int level = leaf.level - 1; level >= 0; --level) {
        const GridPoint a = align(leaf.anchor, level);
        const std::uint64_t code = octree_code(a, level);
        if (nodes_.find(code) != kNoIndex) break;
        nodes_.insert(code, kInternal);
        internal_[level].push_back({a, level});
      }
    }
  }

  bool run() {
    bool changed = false;
    std::array<GridPoint, 6> q;
    for (int level = kOctreeMaxLevel; level >= 1; --level) {
      // Splits only queue nodes of coarser levels, so this list does not grow meanwhile.
      for (const Node& node : internal_[level]) {
        const int count = uncles(node, q);
        for (int i = 0; i < count; ++i)
          if (nodes_.find(octree_code(q[i], level - 1)) != kInternal) {
            make_internal(q[i], level - 1);
            changed = true;
          }
      }
    }
    return changed;
  }

  std::vector<OctreeLeaf> leaves() const {
    std::vector<OctreeLeaf> result;
    result.reserve(leaves_.size());
    for (const Node& n : leaves_)
      if (nodes_.find(octree_code(n.anchor, n.level)) == kLeaf)
        result.push_back({n.anchor, n.level});
    return result;
  }

 private:
  // Splits the leaf covering the node (anchor, level) and its descendants on the way down,
  // the node itself included.
  void make_internal(const GridPoint& anchor, int level) {
    int k = level;
    while (nodes_.find(octree_code(align(anchor, k), k)) == kNoIndex) --k;
    for (; k <= level; ++k) {
      const GridPoint a = align(anchor, k);
      nodes_.insert(octree_code(a, k), kInternal);
      internal_[k].push_back({a, k});
      const std::uint32_t half = (kOctreeGrid >> k) / 2;
      for (int c = 0; c < 8; ++c) {
        const GridPoint child{a[0] + (c & 1) * half, a[1] + (c >> 1 & 1) * half,
                              a[2] + (c >> 2 & 1) * half};
        nodes_.insert(octree_code(child, k + 1), kLeaf);
        leaves_.push_back({child, k + 1});
      }
    }
  }

  KeyMap nodes_;                             // code -> kLeaf or kInternal
  std::vector<std::vector<Node>> internal_;  // internal nodes per level
  std::vector<Node> leaves_;                 // every leaf ever created (some split since)
};

}  // namespace

std::vector<OctreeLeaf> split_balanced(Octree& tree, std::vector<Index> leaves) {
  std::vector<OctreeLeaf> split;
  std::vector<Node> pending;  // internal nodes whose condition is still to be checked
  std::array<GridPoint, 6> q;
  for (;;) {
    for (const Index i : leaves) {
      pending.push_back({tree.leaf(i).anchor, tree.leaf(i).level});
      split.push_back(tree.leaf(i));
    }
    tree.split(leaves);
    leaves.clear();
    std::vector<Node> unmet;
    for (const Node& node : pending) {
      if (node.level == 0) continue;
      const int count = uncles(node, q);
      bool met = true;
      for (int i = 0; i < count; ++i) {
        const Index leaf = tree.leaf_containing(q[i]);
        if (tree.leaf(leaf).level < node.level) {  // q[i] is a leaf or inside one
          leaves.push_back(leaf);
          met = false;
        }
      }
      // One split of a much coarser leaf may not be enough: check again after it.
      if (!met) unmet.push_back(node);
    }
    if (leaves.empty()) return split;
    std::sort(leaves.begin(), leaves.end());
    leaves.erase(std::unique(leaves.begin(), leaves.end()), leaves.end());
    pending = std::move(unmet);
  }
}

void balance(Octree& tree) {
  Balancer balancer(tree);
  if (balancer.run()) tree = Octree(tree.origin(), tree.root_size(), balancer.leaves());
}

}  // namespace volmesh
