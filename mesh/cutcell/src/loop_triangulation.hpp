#pragma once
// Triangulations of one closed contour component inside a cell (the octree paper, §2 and
// §4.1). Loops are point indices in order; triangles follow the loop's orientation. No
// triangle may add a segment to a cell face: a diagonal between two points that lie on a
// common face is refused (`faces` holds a bit per cell face for every point).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::cutcell {

using Triangle = std::array<int, 3>;

struct LoopPoints {
  std::span<const Vec3> position;
  std::span<const std::uint8_t> faces;
};

// Algorithm 1: split the loop along a diagonal whose plane, parallel to the area-weighted
// mean normal, separates the two halves; recurse. Among the valid diagonals the shortest is
// taken. Empty when no valid diagonal exists at some step.
std::optional<std::vector<Triangle>> triangulate_divide_and_conquer(const LoopPoints& points,
                                                                   std::span<const int> loop);

// The triangle fan around `centre`: the centre may be a point of the loop (the cell
// interface point) or a point inside the cell (a feature point, a centroid).
std::vector<Triangle> triangulate_fan(std::span<const int> loop, int centre);

// §4.1's construction for a loop that runs over two faces (a strip between the two chains
// that meet on their common edge) or over three faces around a cube corner (a fan from the
// first inner point of one chain, then from the second point of the next chain). Empty when
// the loop runs over other faces.
std::optional<std::vector<Triangle>> triangulate_across_faces(const LoopPoints& points,
                                                             std::span<const int> loop);

}  // namespace volmesh::cutcell
