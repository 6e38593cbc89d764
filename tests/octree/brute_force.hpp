#pragma once
// Reference answers for the octree tests, computed from the leaf boxes alone.
#include <algorithm>
#include <random>
#include <vector>

#include "volmesh/octree/octree.hpp"

namespace volmesh::test {

// Dimension of the intersection of two closed leaf boxes: -1 (disjoint), 0 (a point),
// 1 (a segment), 2 (a face part), 3 (overlap).
inline int contact_dimension(const OctreeLeaf& a, const OctreeLeaf& b) {
  int dim = 0;
  for (int k = 0; k < 3; ++k) {
    const std::int64_t lo = std::max<std::int64_t>(a.anchor[k], b.anchor[k]);
    const std::int64_t hi =
        std::min<std::int64_t>(a.anchor[k] + a.size(), b.anchor[k] + b.size());
    if (lo > hi) return -1;
    dim += lo < hi;
  }
  return dim;
}

// Leaves sharing a face or an edge part and differing by more than one level.
inline int unbalanced_pairs(const Octree& tree) {
  int count = 0;
  const auto leaves = tree.leaves();
  for (std::size_t i = 0; i < leaves.size(); ++i)
    for (std::size_t j = i + 1; j < leaves.size(); ++j) {
      const int d = contact_dimension(leaves[i], leaves[j]);
      if ((d == 1 || d == 2) && std::abs(leaves[i].level - leaves[j].level) > 1) ++count;
    }
  return count;
}

// Splits random leaves (each with probability p, those below max_level) for a few rounds.
inline Octree random_tree(unsigned seed, int rounds, double p, int max_level) {
  std::mt19937 rng(seed);
  std::bernoulli_distribution coin(p);
  Octree tree(Vec3(-1.0, -2.0, 0.5), 3.0);
  tree.split(std::vector<Index>{0});
  for (int r = 0; r < rounds; ++r) {
    std::vector<Index> chosen;
    for (Index i = 0; i < tree.num_leaves(); ++i)
      if (tree.leaf(i).level < max_level && coin(rng)) chosen.push_back(i);
    tree.split(chosen);
  }
  return tree;
}

}  // namespace volmesh::test
