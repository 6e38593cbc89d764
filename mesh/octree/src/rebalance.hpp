#pragma once
// Incremental 2:1 balance for the refinement loops.
#include <vector>

#include "volmesh/octree/octree.hpp"

namespace volmesh {

// Splits the listed leaves of a balanced tree and restores the balance around them only:
// each split leaf's 18 face and edge neighbours of its size must exist, which may split
// coarser leaves, whose neighbours are checked in turn. Cheaper than balance() when the
// splits are a fraction of the tree.
void split_balanced(Octree& tree, std::vector<Index> leaves);

}  // namespace volmesh
