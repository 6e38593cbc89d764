#pragma once
// A rank's piece of a mesh built on every rank (no rank holding the whole): its cells as a
// mesh of their own, with the numbers the cells and points have over all ranks.
#include <cstdint>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

struct RankPiece {
  // The rank's cells. A face shared with another rank's cell is a boundary face of the
  // piece, oriented out of it, tagged "procBoundary<rank>to<other>".
  PolyMesh mesh;
  // Global numbers over 0 .. count - 1, each cell and point one number on every rank holding
  // it. A cell's is its index in the serial mesher's numbering; a point's too where the
  // mesher can tell it from the point alone (grid), otherwise the ranks number the points
  // they own one after the other (staircase). A point belongs to the lowest rank whose cells
  // use it (point_owner).
  std::vector<std::int64_t> global_cells, global_points;
  std::vector<int> point_owner;
  std::int64_t global_cell_count = 0, global_point_count = 0;
};

}  // namespace volmesh
