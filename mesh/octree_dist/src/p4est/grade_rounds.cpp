#include "grade_rounds.hpp"

#include <mpi.h>
#include <p8est_communication.h>

#include <algorithm>
#include <vector>

#include "volmesh/core/errors.hpp"
#include "volmesh/octree/grade_steps.hpp"

namespace volmesh::octree_dist {
namespace {

// grade() stops at level 2: the buffer of a level-1 leaf is the whole root.
constexpr int kCoarsestGradedLevel = 2;

// The Morton codes of the centres of grade()'s buffer cells at this level around this
// rank's leaves, sorted.
std::vector<std::uint64_t> buffer_centres(p8est_t* forest, int level, int reach) {
  std::vector<OctreeLeaf> leaves;
  for_each_leaf(forest, [&leaves](p8est_quadrant_t& q) { leaves.push_back(to_leaf(q)); });
  std::vector<std::uint64_t> codes;
  for (const GridPoint& p : grade_buffer_centres(grade_covered_cells(leaves, level), level, reach))
    codes.push_back(morton_encode(p));
  return codes;
}

// Each rank's centres to the rank whose stretch of the curve contains them; returns the
// centres this rank received, sorted, each once.
std::vector<std::uint64_t> send_to_owners(p8est_t* forest, const std::vector<std::uint64_t>& centres) {
  const int ranks = forest->mpisize;
  std::vector<int> owner(centres.size()), send_count(ranks, 0);
  int guess = forest->mpirank;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const p8est_quadrant_t q = finest_quadrant(morton_decode(centres[i]));
    owner[i] = guess = p8est_comm_find_owner(forest, 0, &q, guess);
    ++send_count[owner[i]];
  }
  // Centres are sorted by code and stretches follow the curve: owners do not decrease.
  std::vector<int> receive_count(ranks), send_offset(ranks + 1, 0), receive_offset(ranks + 1, 0);
  MPI_Alltoall(send_count.data(), 1, MPI_INT, receive_count.data(), 1, MPI_INT, forest->mpicomm);
  for (int r = 0; r < ranks; ++r) {
    send_offset[r + 1] = send_offset[r] + send_count[r];
    receive_offset[r + 1] = receive_offset[r] + receive_count[r];
  }
  std::vector<std::uint64_t> received(receive_offset[ranks]);
  MPI_Alltoallv(centres.data(), send_count.data(), send_offset.data(), MPI_UINT64_T, received.data(),
                receive_count.data(), receive_offset.data(), MPI_UINT64_T, forest->mpicomm);
  std::sort(received.begin(), received.end());
  received.erase(std::unique(received.begin(), received.end()), received.end());
  return received;
}

struct GradeStage {
  const std::vector<std::uint64_t>& centres;  // sorted
  int level;
};

// A leaf coarser than the level holding a centre: a leaf covers the Morton codes
// [code(anchor), code(anchor) + size^3).
int split_at_centres(p8est_t* forest, p4est_topidx_t, p8est_quadrant_t* q) {
  const auto& stage = *static_cast<const GradeStage*>(forest->user_pointer);
  if (q->level >= stage.level) return 0;
  const OctreeLeaf leaf = to_leaf(*q);
  const std::uint64_t first = morton_encode(leaf.anchor), size = leaf.size();
  const auto it = std::lower_bound(stage.centres.begin(), stage.centres.end(), first);
  return it != stage.centres.end() && *it < first + size * size * size;
}

int deepest_level(p8est_t* forest) {
  int level = 0;
  for_each_leaf(forest, [&level](p8est_quadrant_t& q) { level = std::max<int>(level, q.level); });
  int deepest = 0;
  MPI_Allreduce(&level, &deepest, 1, MPI_INT, MPI_MAX, forest->mpicomm);
  return deepest;
}

}  // namespace

int grade_rounds(p8est_t* forest, int cells_between_levels) {
  if (cells_between_levels < 1) throw InputError("--cells-between-levels must be at least 1");
  const int reach = cells_between_levels - 1;
  if (reach == 0) return 0;
  int graded = 0;
  for (int level = deepest_level(forest); level >= kCoarsestGradedLevel; --level) {
    // Fixed before splitting, as in grade(): leaves the buffer makes do not widen it.
    const std::vector<std::uint64_t> centres = send_to_owners(forest, buffer_centres(forest, level, reach));
    GradeStage stage{centres, level};
    graded += refine_until_stable(forest, split_at_centres, &stage) > 0;
  }
  return graded;
}

}  // namespace volmesh::octree_dist
