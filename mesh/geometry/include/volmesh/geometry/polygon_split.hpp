#pragma once
// How a polygonal face is cut into triangles for integration: the fan around its vertex
// average (what OpenFOAM and core/geometry use) when that fan faces one way, otherwise an
// ear clipping or the fan when either does not cross itself in space; a face where neither
// works is folded over itself, and no cell on it can be split into positive pieces. The
// polyhedral FEM integrates with this split; the cut-cell mesher refuses to make a folded
// face with it.
#include <array>
#include <span>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh {

struct PolygonSplit {
  // Corners as loop positions, position loop.size() standing for the vertex average; empty
  // when the fan around the vertex average is used.
  std::vector<std::array<int, 3>> triangles;
  bool folded = false;
};
PolygonSplit split_polygon(const std::vector<Vec3>& points, std::span<const Index> loop);

// The fan around the vertex average of a polygon of n vertices, as above.
std::vector<std::array<int, 3>> fan_triangles(std::size_t n);

}  // namespace volmesh
