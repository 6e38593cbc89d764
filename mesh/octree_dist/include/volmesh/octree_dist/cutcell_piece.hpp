#pragma once
// Each rank's piece of the cut-cell mesh (volmesh/cutcell/cutcell.hpp): the distributed octree
// with kCutcellGhostLayers ghost layers, the serial pipeline on the rank's window (its leaves,
// the ghosts, coarse fillers tiling the rest of the root), and of the window's cells those the
// rank owns. The stages that reach beyond a leaf (the extra refinement rules, the vertex moves,
// the reflex splits and the merging) see, around every cell the rank keeps, the leaves the
// serial run sees there (docs/distributed.md, "Cut cells").
#include "volmesh/cutcell/cutcell.hpp"
#include "volmesh/octree_dist/rank_piece.hpp"

namespace volmesh {

// Ghost layers around a rank's leaves: one for the cells of a leaf (its neighbours' points),
// one for the vertex moves around them, and what the extra refinement's balance and the
// merges reach beyond (three layers fall short on fandisk.off at level 6 on four ranks).
inline constexpr int kCutcellGhostLayers = 4;

// Collective over MPI_COMM_WORLD. A cell belongs to the rank whose stretch of the Morton
// curve holds the lowest of its vertices (lexicographically by coordinates): every rank
// computing the cell alike finds the same. Cells are numbered rank after rank, points by their
// places (the same bits on every rank computing them), owned by the lowest rank using them.
// Throws as cutcell_mesh, and InputError in a build without p4est.
RankPiece cutcell_piece(const Domain& domain, const CutcellOptions& options);

}  // namespace volmesh
