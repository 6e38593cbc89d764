#pragma once
// A rank's piece cut out of the mesh it computed over its window (its leaves, ghosts and
// fillers): its cells, their points numbered over all ranks, owned by the lowest rank whose
// cells use them.
#include <mpi.h>

#include <algorithm>
#include <vector>

#include "point_numbering.hpp"
#include "volmesh/octree_dist/rank_piece.hpp"
#include "volmesh/partition/part_mesh.hpp"

namespace volmesh::octree_dist {

// cell_part: each cell's rank, `parts - 1` or beyond for cells no rank keeps; every cell using
// a point of the rank's cells must be in `whole`. key_of(point) gives a point's key
// (point_numbering.hpp). Cells are numbered rank after rank in their order in `whole`.
// Collective.
template <class KeyOf>
RankPiece window_piece(const PolyMesh& whole, const std::vector<Index>& cell_part, int rank, Index parts,
                       KeyOf key_of) {
  // A point's owner: the lowest rank among the cells using it.
  std::vector<int> lowest(whole.num_points(), static_cast<int>(parts));
  for (Index f = 0; f < whole.num_faces(); ++f) {
    Index part = cell_part[whole.owner[f]];
    if (!whole.is_boundary(f)) part = std::min(part, cell_part[whole.neighbour[f]]);
    for (const Index v : whole.face(f)) lowest[v] = std::min(lowest[v], static_cast<int>(part));
  }
  PartMesh mine = std::move(split_mesh(whole, cell_part, parts)[rank]);

  RankPiece out;
  out.mesh = std::move(mine.mesh);
  const std::int64_t cells = out.mesh.num_cells();
  std::int64_t first_cell = 0;
  MPI_Exscan(&cells, &first_cell, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) first_cell = 0;  // MPI_Exscan leaves rank 0's undefined
  MPI_Allreduce(&cells, &out.global_cell_count, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
  out.global_cells.resize(cells);
  for (std::int64_t c = 0; c < cells; ++c) out.global_cells[c] = first_cell + c;

  using Key = decltype(key_of(Vec3{}));
  std::vector<Key> keys(mine.global_points.size());
  std::vector<int> owner(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    keys[i] = key_of(whole.points[mine.global_points[i]]);
    owner[i] = lowest[mine.global_points[i]];
  }
  PointNumbers numbers = number_points(keys, owner, MPI_COMM_WORLD);
  out.global_points = std::move(numbers.id);
  out.global_point_count = numbers.count;
  out.point_owner = std::move(owner);
  return out;
}

}  // namespace volmesh::octree_dist
