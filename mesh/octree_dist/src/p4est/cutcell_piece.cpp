// A rank's cut-cell piece: the serial pipeline (cutcell_mesh_of_tree) on the rank's window,
// balanced so that the fillers tile the root as a 2:1 tree (the coarsest balanced refinement,
// which leaves the rank's leaves and its ghosts whole: the whole tree refines it and is
// balanced), then the cells the rank owns.
#include "volmesh/octree_dist/cutcell_piece.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "local_tree.hpp"
#include "volmesh/cutcell/cutcell_tree.hpp"
#include "volmesh/octree_dist/distributed_octree.hpp"
#include "window_piece.hpp"

namespace volmesh {
namespace {

using octree_dist::cell_code;

// Per rank, the Morton code its stretch starts at (a rank without leaves: the next rank's).
std::vector<std::uint64_t> stretch_starts(const DistributedOctree& tree) {
  const std::uint64_t mine = tree.leaves.empty() ? std::numeric_limits<std::uint64_t>::max()
                                                 : morton_encode(tree.leaves.front().anchor);
  std::vector<std::uint64_t> starts(tree.ranks);
  MPI_Allgather(&mine, 1, MPI_UINT64_T, starts.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD);
  for (int r = tree.ranks - 2; r >= 0; --r) starts[r] = std::min(starts[r], starts[r + 1]);
  starts.front() = 0;
  return starts;
}

// Per cell, the lowest of its vertices, lexicographically by coordinates.
std::vector<Vec3> lowest_vertices(const PolyMesh& mesh) {
  constexpr double kFar = std::numeric_limits<double>::infinity();
  std::vector<Vec3> lowest(mesh.num_cells(), Vec3::Constant(kFar));
  const auto below = [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
  };
  for (Index f = 0; f < mesh.num_faces(); ++f)
    for (const Index v : mesh.face(f)) {
      const Vec3& x = mesh.points[v];
      if (below(x, lowest[mesh.owner[f]])) lowest[mesh.owner[f]] = x;
      if (!mesh.is_boundary(f) && below(x, lowest[mesh.neighbour[f]])) lowest[mesh.neighbour[f]] = x;
    }
  return lowest;
}

}  // namespace

RankPiece cutcell_piece(const Domain& domain, const CutcellOptions& options) {
  const DistributedOctree distributed = build_distributed_octree(domain, options.octree, kCutcellGhostLayers);
  const std::vector<std::uint64_t> starts = stretch_starts(distributed);
  PolyMesh whole;  // a rank without leaves (more ranks than leaves) keeps no cell
  if (!distributed.leaves.empty()) {
    Octree tree(distributed.root.origin, distributed.root.side, octree_dist::local_tree(distributed).leaves);
    balance(tree);
    CutcellOptions window = options;
    window.progress = nullptr;  // the ranks' progress is rank 0's line, not the pipeline's stages
    whole = cutcell_mesh_of_tree(std::move(tree), domain, window);
  }
  const Octree frame(distributed.root.origin, distributed.root.side);  // for cell_code

  const std::vector<Vec3> lowest = lowest_vertices(whole);
  std::vector<Index> cell_part(whole.num_cells());
  for (Index c = 0; c < whole.num_cells(); ++c) {
    const std::uint64_t code = cell_code(frame, lowest[c]);
    cell_part[c] = static_cast<Index>(std::upper_bound(starts.begin(), starts.end(), code) - starts.begin()) - 1;
  }
  return octree_dist::window_piece(whole, cell_part, distributed.rank, distributed.ranks,
                                   [](const Vec3& x) { return octree_dist::place_key(x); });
}

}  // namespace volmesh
