#pragma once
// Global numbers for points that several ranks hold, each known by its key and its owner (a
// rank that holds it; every holder names the same). A key is the Morton code of a grid point
// (GridKey) or the bits of a point's coordinates (PlaceKey), which ranks that compute a point
// from the same inputs get alike.
#include <array>
#include <cstdint>
#include <mpi.h>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::octree_dist {

using GridKey = std::uint64_t;
using PlaceKey = std::array<std::uint64_t, 3>;
PlaceKey place_key(const Vec3& x);

struct PointNumbers {
  std::vector<std::int64_t> id;  // per point
  std::int64_t count = 0;        // over all ranks
};

// Each rank numbers the points it owns in key order after the lower ranks' (an exclusive
// scan); the other holders ask the owners for the numbers (two all-to-all exchanges). Keys
// each once per rank. Throws InputError (after the exchanges) on a rank that asks an owner
// for a point the owner does not hold: the ranks computed it differently.
PointNumbers number_points(const std::vector<GridKey>& keys, const std::vector<int>& owner, MPI_Comm comm);
PointNumbers number_points(const std::vector<PlaceKey>& keys, const std::vector<int>& owner, MPI_Comm comm);

}  // namespace volmesh::octree_dist
