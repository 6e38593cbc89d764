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

// Balance check for trees too large for the pairwise test: every leaf adjacent to a face
// (or an edge) of a leaf of level l contains one of the points sampled on the level-(l+2)
// grid just across it, so the levels found there bound the neighbours' levels.
inline int sampled_balance_violations(const Octree& tree) {
  int violations = 0;
  for (Index i = 0; i < tree.num_leaves(); ++i) {
    const OctreeLeaf& c = tree.leaf(i);
    const std::int64_t s = c.size(), q = std::max<std::int64_t>(1, s / 4);
    auto check = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
      if (x < 0 || y < 0 || z < 0 || x >= kOctreeGrid || y >= kOctreeGrid || z >= kOctreeGrid)
        return;
      const Index d = tree.leaf_containing({static_cast<std::uint32_t>(x),
                                            static_cast<std::uint32_t>(y),
                                            static_cast<std::uint32_t>(z)});
      violations += std::abs(tree.leaf(d).level - c.level) > 1;
    };
    for (int a = 0; a < 3; ++a) {
      const int u = (a + 1) % 3, v = (a + 2) % 3;
      for (const std::int64_t side : {std::int64_t{-1}, s})  // faces
        for (std::int64_t du = 0; du < s; du += q)
          for (std::int64_t dv = 0; dv < s; dv += q) {
            std::array<std::int64_t, 3> p{c.anchor[0], c.anchor[1], c.anchor[2]};
            p[a] += side;
            p[u] += du;
            p[v] += dv;
            check(p[0], p[1], p[2]);
          }
      for (const std::int64_t su : {std::int64_t{-1}, s})  // edges along a
        for (const std::int64_t sv : {std::int64_t{-1}, s})
          for (std::int64_t da = 0; da < s; da += q) {
            std::array<std::int64_t, 3> p{c.anchor[0], c.anchor[1], c.anchor[2]};
            p[a] += da;
            p[u] += su;
            p[v] += sv;
            check(p[0], p[1], p[2]);
          }
    }
  }
  return violations;
}

}  // namespace volmesh::test
