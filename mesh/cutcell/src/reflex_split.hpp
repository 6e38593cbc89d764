#pragma once
// Cells split at a reflex edge of the domain's surface. Where a sharp edge of a boundary or
// interface crosses a cube so that the region wrapping it keeps an L-shaped piece, the
// piece's centre lies beyond its own faces, and joining those faces into polygons bent
// across the edge (the agglomeration's remedy) cuts or fills the edge by a fraction of the
// cell. Instead the piece is cut in two by the plane of one of the edge's faces: each part
// lies on one side of it, and the edge stays where the cutting put it. The plane cuts other
// faces of the cell along chords; a point it puts on an edge of the cell is put into every
// face of the mesh around that edge, so that no face misses a vertex on its sides.
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/quality/face_metrics.hpp"

namespace volmesh::cutcell {

// Splits the cells of `mesh` that checkMesh would reject and that have a reflex edge between
// two planar faces of the domain's surface (boundary faces or faces between regions), when
// that leaves both parts better. cell_size: the edge of each cell's leaf, extended for the
// new cells. Returns the number of cells split.
Index split_reflex_cells(PolyMesh& mesh, std::vector<double>& cell_size, const CheckMeshLimits& limits);

}  // namespace volmesh::cutcell
