#pragma once
// Each rank's piece of the staircase mesh (volmesh/octree/staircase.hpp) of a distributed
// octree: the cells of its own leaves, computed from its leaves and the ghost layer, so that
// a face or a point shared with another rank is computed alike on both sides.
#include <cstdint>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/octree_dist/distributed_octree.hpp"

namespace volmesh {

struct StaircasePiece {
  // The rank's cells, in Morton order. A face shared with another rank's cell is a boundary
  // face of the piece, oriented out of it, tagged "procBoundary<rank>to<other>".
  PolyMesh mesh;
  // Global numbers: a cell's is its index in staircase_mesh's numbering (the ranks' cells
  // in rank order); a point's is numbered by the lowest rank whose cells use it, rank by
  // rank, in Morton order within a rank. Both run over 0 .. count - 1.
  std::vector<std::int64_t> global_cells, global_points;
  std::int64_t global_cell_count = 0, global_point_count = 0;
};

// Collective over the octree's ranks. Over all ranks the cells are staircase_mesh's for the
// same domain and options.
StaircasePiece staircase_piece(const DistributedOctree& tree, const Domain& domain);

}  // namespace volmesh
