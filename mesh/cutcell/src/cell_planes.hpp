#pragma once
// The planes of a cell's six faces (through their centres, along their mean normals, which
// stay planes when vertex moves warp the faces), and points kept inside them.
#include <array>
#include <optional>

#include "volmesh/core/types.hpp"

namespace volmesh::cutcell {

// Distance of p inside the hexahedron with these corners (negative outside), measured from
// the planes of its faces. Corner k lies at offset (k & 1, k >> 1 & 1, k >> 2 & 1).
double depth_inside_cell(const std::array<Vec3, 8>& corners, const Vec3& p);
// p pushed inside until it lies `margin` from every face plane; nullopt when it lies farther
// than `reach` outside.
std::optional<Vec3> clamp_into_cell(const std::array<Vec3, 8>& corners, Vec3 p, double margin,
                                    double reach);
// p moved along `direction` (either way, the least distance) until it lies `margin` from
// every face plane; nullopt when no such move reaches it within `reach`.
std::optional<Vec3> slide_into_cell(const std::array<Vec3, 8>& corners, const Vec3& p, const Vec3& direction,
                                    double margin, double reach);

}  // namespace volmesh::cutcell
