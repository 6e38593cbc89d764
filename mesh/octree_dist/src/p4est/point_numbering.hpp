#pragma once
// Global numbers for points that several ranks hold, each known by its key (the Morton code
// of its grid point) and its owner (a rank that holds it; every holder names the same).
#include <cstdint>
#include <mpi.h>
#include <vector>

namespace volmesh::octree_dist {

struct PointNumbers {
  std::vector<std::int64_t> id;  // per point
  std::int64_t count = 0;        // over all ranks
};

// Each rank numbers the points it owns in key order after the lower ranks' (an exclusive
// scan); the other holders ask the owners for the numbers (two all-to-all exchanges).
// `keys` sorted, each once.
PointNumbers number_points(const std::vector<std::uint64_t>& keys, const std::vector<int>& owner, MPI_Comm comm);

}  // namespace volmesh::octree_dist
