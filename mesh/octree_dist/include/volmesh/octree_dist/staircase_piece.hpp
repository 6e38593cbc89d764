#pragma once
// Each rank's piece of the staircase mesh (volmesh/octree/staircase.hpp) of a distributed
// octree: the cells of its own leaves, computed from its leaves and the ghost layer, so that
// a face or a point shared with another rank is computed alike on both sides.
#include "volmesh/octree_dist/distributed_octree.hpp"
#include "volmesh/octree_dist/rank_piece.hpp"

namespace volmesh {

// Collective over the octree's ranks. Over all ranks the cells are staircase_mesh's for the
// same domain and options, in Morton order on each rank.
RankPiece staircase_piece(const DistributedOctree& tree, const Domain& domain);

}  // namespace volmesh
