#pragma once
// Automatic refinement of a contoured hex mesh where the solid is thin or its surface strongly
// curved, read from the signed-distance field it was contoured from, so that no part of the
// solid is one node wide (every node of it pinned to the surface) and no boundary hex spans
// more curvature than its outer quad can follow.
//
// The measures, per hex with a node on a boundary quad, over the field's samples in the hex's
// bounding box:
//   width  : the shortest run of inside samples (>= 0) between two outside ones along a grid
//            line through the box, crossing to crossing (linear interpolation): a hex is thin
//            when the part it lies in is narrower than kThinCells of its mean edges along an
//            axis (a plate oblique to the axes reads up to sqrt(3) times its thickness);
//   spread : the largest angle between the field's normals (central differences) at the
//            crossings in the box and their mean: a hex is curved beyond kCurvedAngleDeg.
// Hexes one hex across (two opposite faces on the boundary) are taken first, then thin ones,
// the narrowest first, then curved ones, the most curved first (ties in hex order): each marks its eight corners, the marks are closed over the neighbours
// (refine.hpp's closure, a worklist from the new marks) and the step is undone when the mesh
// would then pass max_growth times its hexes plus boundary quads before (the buffer layer adds
// one hex per boundary quad, so this bounds the final mesh), or when it would split a hex with
// a nearly collapsed edge (its children would have coinciding nodes). The marks kept are
// refined by refine_hexes.
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/voxel_grid.hpp"
#include "volmesh/hexdc/refine.hpp"

namespace volmesh {

// The final mesh has at most this many times the hexes it would have without the refinement.
inline constexpr double kThinGrowth = 2.0;
// A part narrower than this many hex edges is thin: "one node wide" once contoured.
inline constexpr double kThinCells = 2.0;
// A boundary hex whose surface normals spread beyond this angle is curved.
inline constexpr double kCurvedAngleDeg = 45.0;

struct ThinRefineStats {
  Index thin_hexes = 0;    // hexes across a part narrower than kThinCells hex edges
  Index curved_hexes = 0;  // boundary hexes, not thin, with normals spread beyond kCurvedAngleDeg
  Index thin_refined = 0, curved_refined = 0;  // of them, refined within the bound
  Index skipped_collapsed = 0;  // left out as they would split a hex with a collapsed edge
  Index hexes_before = 0, hexes_after = 0;
  Index boundary_quads_before = 0, boundary_quads_after = 0;
  RefineStats refinement;  // of the marks kept
};

// Seeds with a point of `first` in their bounding box grown by a mean edge are taken before
// the others (the mesher passes the failing hexes of a refused mesh).
ThinRefineStats refine_thin_parts(HexMesh& mesh, const VoxelGrid& field,
                                  const std::vector<Vec3>& first = {},
                                  double max_growth = kThinGrowth);

}  // namespace volmesh
