#pragma once
// Closing a stalled front: the cavity it bounds is meshed by the projection mesher
// (projection.hpp, rounding.hpp) and merged in.
#include <array>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::tet::front {

// Tets filling the cavity bounded by `faces` (each facing into it), their new points appended
// to `points`. Throws InputError when no projection direction meshes the cavity without
// splitting its faces (the merged mesh would not be conforming).
std::vector<std::array<Index, 4>> close_cavity(std::vector<Vec3>& points,
                                               const std::vector<std::array<Index, 3>>& faces);

}  // namespace volmesh::tet::front
