#pragma once
// A rank's window of a distributed octree as a tree of its own: its leaves, its ghosts and,
// to tile the root, the coarsest nodes filling the gaps between them (fillers).
#include <vector>

#include "volmesh/octree_dist/distributed_octree.hpp"

namespace volmesh::octree_dist {

struct LocalTree {
  std::vector<OctreeLeaf> leaves;  // Morton order, tiling the root
  std::vector<int> part;           // per leaf: the owning rank; `ranks` for a filler
};

LocalTree local_tree(const DistributedOctree& tree);

// The Morton code of the finest grid cell holding world point x (clamped to the root):
// rank r's leaves hold the codes from its first leaf's up to the next rank's.
std::uint64_t cell_code(const Octree& tree, const Vec3& x);

}  // namespace volmesh::octree_dist
