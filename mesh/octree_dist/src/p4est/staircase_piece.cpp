// A rank's staircase piece: staircase_cells on the rank's window (local_tree.hpp). Every leaf
// that touches one of the rank's leaves is a ghost or its own, so the rank's cells, their
// faces and the vertices on them are the whole tree's; the fillers' cells, which the 2:1
// balance does not hold for, and the ghosts' are dropped.
#include "volmesh/octree_dist/staircase_piece.hpp"

#include <cmath>

#include "local_tree.hpp"
#include "volmesh/octree/staircase.hpp"
#include "window_piece.hpp"

namespace volmesh {
namespace {

// The grid point at world position x (a vertex of the tree: exact up to rounding).
octree_dist::GridKey grid_key(const Octree& tree, const Vec3& x) {
  const double unit = tree.root_size() / kOctreeGrid;
  GridPoint p;
  for (int a = 0; a < 3; ++a) p[a] = static_cast<std::uint32_t>(std::llround((x[a] - tree.origin()[a]) / unit));
  return morton_encode(p);
}

}  // namespace

RankPiece staircase_piece(const DistributedOctree& distributed, const Domain& domain) {
  octree_dist::LocalTree local = octree_dist::local_tree(distributed);
  const Octree tree(distributed.root.origin, distributed.root.side, std::move(local.leaves));
  std::vector<Index> cell_leaf;
  const PolyMesh whole = staircase_cells(tree, domain, &cell_leaf);
  std::vector<Index> cell_part(whole.num_cells());
  for (Index c = 0; c < whole.num_cells(); ++c) cell_part[c] = local.part[cell_leaf[c]];
  // The piece's points keep the whole's order, the Morton order of their grid points.
  return octree_dist::window_piece(whole, cell_part, distributed.rank, distributed.ranks + 1,
                                   [&tree](const Vec3& x) { return grid_key(tree, x); });
}

}  // namespace volmesh
