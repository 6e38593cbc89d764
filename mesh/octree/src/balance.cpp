// 2:1 balance across faces and edges. Formulation: for every internal node at level k >= 1,
// its 18 face and edge neighbours at level k must exist as nodes (leaf or internal); then no
// leaf sharing part of a face or an edge with a leaf of level l is coarser than l - 1.
// Internal nodes are processed from the deepest level up; a missing neighbour is created by
// splitting the leaf that covers it, whose new internal nodes are queued at their (coarser)
// level. Each node is visited once.
#include <algorithm>
#include <vector>

#include "volmesh/octree/octree.hpp"

namespace volmesh {

namespace {

constexpr Index kInternal = 0, kLeaf = 1;

struct Node {
  GridPoint anchor;
  int level;
};

// The 18 offsets with one or two non-zero components: faces and edges.
std::vector<std::array<int, 3>> face_and_edge_offsets() {
  std::vector<std::array<int, 3>> offsets;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nonzero = (dx != 0) + (dy != 0) + (dz != 0);
        if (nonzero == 1 || nonzero == 2) offsets.push_back({dx, dy, dz});
      }
  return offsets;
}

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
    const auto offsets = face_and_edge_offsets();
    bool changed = false;
    for (int level = kOctreeMaxLevel; level >= 1; --level) {
      // Splits only queue nodes of coarser levels, so this list does not grow meanwhile.
      for (const Node& node : internal_[level]) {
        const std::int64_t s = kOctreeGrid >> level;
        for (const auto& d : offsets) {
          GridPoint n;
          bool inside = true;
          for (int a = 0; a < 3; ++a) {
            const std::int64_t c = node.anchor[a] + d[a] * s;
            inside = inside && c >= 0 && c < kOctreeGrid;
            n[a] = static_cast<std::uint32_t>(c);
          }
          if (inside && nodes_.find(octree_code(n, level)) == kNoIndex) {
            create(n, level);
            changed = true;
          }
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
  static GridPoint align(const GridPoint& p, int level) {
    const std::uint32_t mask = ~((kOctreeGrid >> level) - 1);
    return {p[0] & mask, p[1] & mask, p[2] & mask};
  }

  // Splits the leaf covering (anchor, level) and its descendants on the way down until the
  // node exists.
  void create(const GridPoint& anchor, int level) {
    int k = level - 1;
    while (nodes_.find(octree_code(align(anchor, k), k)) == kNoIndex) --k;
    for (; k < level; ++k) {
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

  KeyMap nodes_;                           // code -> kLeaf or kInternal
  std::vector<std::vector<Node>> internal_;  // internal nodes per level
  std::vector<Node> leaves_;               // every leaf ever created (some split since)
};

}  // namespace

void balance(Octree& tree) {
  Balancer balancer(tree);
  if (balancer.run()) tree = Octree(tree.origin(), tree.root_size(), balancer.leaves());
}

}  // namespace volmesh
