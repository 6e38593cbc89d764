// A rank's staircase piece: staircase_cells on a tree made of the rank's leaves, its ghosts
// and, to tile the root, the coarsest nodes filling the gaps between them (fillers). Every
// leaf that touches one of the rank's leaves is a ghost or its own, so the rank's cells,
// their faces and the vertices on them are the whole tree's; the fillers' cells, which the
// 2:1 balance does not hold for, and the ghosts' are dropped.
#include "volmesh/octree_dist/staircase_piece.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>

#include "point_numbering.hpp"
#include "volmesh/octree/staircase.hpp"
#include "volmesh/partition/part_mesh.hpp"

namespace volmesh {
namespace {

using octree_dist::number_points;

struct LocalTree {
  std::vector<OctreeLeaf> leaves;  // Morton order, tiling the root
  std::vector<int> part;           // per leaf: the owning rank; `ranks` for a filler
};

std::uint64_t curve_length(const OctreeLeaf& leaf) {
  const std::uint64_t s = leaf.size();
  return s * s * s;
}

// The Morton curve's stretch [from, to) as the largest aligned nodes, in order.
void fill(std::uint64_t from, std::uint64_t to, int part, LocalTree& out) {
  while (from < to) {
    int k = kOctreeMaxLevel;  // a node of edge 2^k spans 8^k codes
    while (k > 0 && ((from & ((std::uint64_t{1} << 3 * k) - 1)) != 0 || from + (std::uint64_t{1} << 3 * k) > to)) --k;
    out.leaves.push_back({morton_decode(from), kOctreeMaxLevel - k});
    out.part.push_back(part);
    from += std::uint64_t{1} << 3 * k;
  }
}

LocalTree local_tree(const DistributedOctree& tree) {
  LocalTree out;
  std::uint64_t next = 0;  // where the curve is covered up to
  const auto add = [&](const OctreeLeaf& leaf, int part) {
    const std::uint64_t first = morton_encode(leaf.anchor);
    fill(next, first, tree.ranks, out);
    out.leaves.push_back(leaf);
    out.part.push_back(part);
    next = first + curve_length(leaf);
  };
  std::size_t g = 0;
  for (const OctreeLeaf& leaf : tree.leaves) {
    for (; g < tree.ghosts.size() && morton_encode(tree.ghosts[g].anchor) < morton_encode(leaf.anchor); ++g)
      add(tree.ghosts[g], tree.ghost_owner[g]);
    add(leaf, tree.rank);
  }
  for (; g < tree.ghosts.size(); ++g) add(tree.ghosts[g], tree.ghost_owner[g]);
  fill(next, std::uint64_t{1} << 3 * kOctreeMaxLevel, tree.ranks, out);
  return out;
}

// The grid point at world position x (a vertex of the tree: exact up to rounding).
std::uint64_t grid_key(const Octree& tree, const Vec3& x) {
  const double unit = tree.root_size() / kOctreeGrid;
  GridPoint p;
  for (int a = 0; a < 3; ++a) p[a] = static_cast<std::uint32_t>(std::llround((x[a] - tree.origin()[a]) / unit));
  return morton_encode(p);
}

}  // namespace

RankPiece staircase_piece(const DistributedOctree& distributed, const Domain& domain) {
  LocalTree local = local_tree(distributed);
  const Octree tree(distributed.root.origin, distributed.root.side, std::move(local.leaves));
  std::vector<Index> cell_leaf;
  const PolyMesh whole = staircase_cells(tree, domain, &cell_leaf);
  std::vector<Index> cell_part(whole.num_cells());
  for (Index c = 0; c < whole.num_cells(); ++c) cell_part[c] = local.part[cell_leaf[c]];
  // A point's owner: the lowest rank among the cells using it (all of them are here).
  std::vector<int> lowest(whole.num_points(), distributed.ranks);
  for (Index f = 0; f < whole.num_faces(); ++f) {
    int part = cell_part[whole.owner[f]];
    if (!whole.is_boundary(f)) part = std::min(part, cell_part[whole.neighbour[f]]);
    for (const Index v : whole.face(f)) lowest[v] = std::min(lowest[v], part);
  }
  PartMesh mine = std::move(split_mesh(whole, cell_part, distributed.ranks + 1)[distributed.rank]);

  RankPiece out;
  out.mesh = std::move(mine.mesh);
  const std::int64_t cells = out.mesh.num_cells();
  std::int64_t first_cell = 0;
  MPI_Exscan(&cells, &first_cell, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
  if (distributed.rank == 0) first_cell = 0;  // MPI_Exscan leaves rank 0's undefined
  MPI_Allreduce(&cells, &out.global_cell_count, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
  out.global_cells.resize(cells);
  for (std::int64_t c = 0; c < cells; ++c) out.global_cells[c] = first_cell + c;

  // The piece's points keep the whole's order, the Morton order of their grid points.
  std::vector<std::uint64_t> keys(mine.global_points.size());
  std::vector<int> owner(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    keys[i] = grid_key(tree, whole.points[mine.global_points[i]]);
    owner[i] = lowest[mine.global_points[i]];
  }
  octree_dist::PointNumbers numbers = number_points(keys, owner, MPI_COMM_WORLD);
  out.global_points = std::move(numbers.id);
  out.global_point_count = numbers.count;
  out.point_owner = std::move(owner);
  return out;
}

}  // namespace volmesh
