#pragma once
// Each rank's piece of the grid method's hexahedra (2^level per axis of a box): the cells of
// its stretch of the Morton curve over the level's uniform grid, the curve split as evenly as
// p8est_new splits a uniform forest. No rank builds more than its own cells.
#include "volmesh/domain/domain.hpp"
#include "volmesh/octree_dist/rank_piece.hpp"

namespace volmesh {

// Collective over MPI_COMM_WORLD. Over all ranks the cells are structured_hex_mesh's with the
// same numbers, points (with their numbers) and boundary tags. Throws InputError in a build
// without p4est.
RankPiece grid_piece(const Box3& box, int level);

}  // namespace volmesh
