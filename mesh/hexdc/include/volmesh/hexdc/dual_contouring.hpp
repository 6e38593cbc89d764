#pragma once
// The uniform dual-contouring hex mesh, the first stage of the hexdc mesher (no smoothing,
// pillowing or refinement).
//
// The field is a signed distance on a (2^k + 1)^3 grid, positive inside and negative outside
// (VoxelGrid's convention, the paper's). At octree level L (1 <= L <= k) the grid splits into
// 2^L nodes per axis, each a cube of 2^(k-L) voxels along an axis. A node with a sample
// F >= 0 among its (2^(k-L) + 1)^3 gets a mesh vertex:
//   - every sample >= 0 (an interior node): the node's centre;
//   - samples of both signs (a boundary node): solve_qef over the isosurface crossings of
//     every voxel edge in the node (linear interpolation of F along the edge; the normal is
//     the central-difference gradient interpolated likewise, normalised).
// Each 2x2x2 block of neighbouring nodes that all have vertices gives a hex, corners in VTK
// order (x, then y, then z), so that a block of axis-aligned vertices has positive volume,
// except blocks left out so that the boundary is a manifold at every node: where hexes meet
// at an edge or a vertex only, or the outside is pinched to an edge or a vertex (two sheets of
// the surface in one node at a thin part), no boundary node has an inward direction that
// the buffer layer could offset it along. Those hexes are removed at each such node (the
// smaller of the hex groups meeting there, or those between the outside's parts), repeated
// until every node is a manifold one.
#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/core/voxel_grid.hpp"

namespace volmesh {

// Deepest grid whose (2^k + 1)^3 samples an Index counts (2049^3 would not fit).
inline constexpr int kHexdcMaxDepth = 10;

struct HexdcStats {
  Index nodes_per_axis = 0;      // 2^L
  Index interior_vertices = 0;   // nodes with every sample >= 0
  Index boundary_vertices = 0;   // nodes with samples of both signs
  Index qef_fallbacks = 0;       // boundary vertices left at the mass point (solve_qef)
  Index nonmanifold_blocks_removed = 0;  // blocks left out to keep the boundary a manifold
  Index unused_vertices = 0;     // vertices in no hex, left out of the mesh
  Index hexes = 0;
  Index invalid_hexes = 0;       // failing the ten corner tets (hex_corner_tets_positive)
};

// One region (1); every boundary face tagged "boundary". Vertices in no hex are left out.
// Throws InputError for dims other than 2^k + 1 (k >= 1, the same on all three axes), a level
// outside [1, k], no sample >= 0, or no hex at this level. `stats` may be null.
PolyMesh hexdc_uniform(const VoxelGrid& field, int level, HexdcStats* stats);

}  // namespace volmesh
