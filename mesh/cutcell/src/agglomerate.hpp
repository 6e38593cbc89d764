#pragma once
// The last step of the cut-cell mesher: cells that OpenFOAM's checkMesh would reject, or
// that are tiny, merged into a neighbouring cell of their own region. Cutting a cube along a
// curved interface or at a junction of several can leave a thin or bent piece whose centre
// lies beyond one of its faces (checkMesh's "incorrectly oriented" face pyramids), beside a
// face nearly parallel to the line between the centres (non-orthogonality of 90° or more),
// or far from the centre of a small face (skewness). The union with a neighbour moves the
// centre back where the faces expect it; two faces between the same two cells may also be
// joined into one polygon (a sliver triangle's normal is all but arbitrary). No point
// moves: the union of two cells is closed as each of them was and keeps their volume; a
// joined polygon is decomposed about its own centre, which moves the interface there by
// less than its warp: the region volumes change far less than the discretisation error.
#include <vector>

#include "volmesh/core/geometry.hpp"
#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/quality/face_metrics.hpp"

namespace volmesh::cutcell {

struct AgglomerationOptions {
  CheckMeshLimits limits;          // a cell with a face beyond them is merged
  double min_volume_ratio = 0.0;   // cells below this * size^3 are merged too
  int rounds = 16;
};

struct AgglomerationStats {
  Index merged = 0;     // merges of a cell with one or two neighbours
  Index joined = 0;     // faces joined with a neighbouring face between the same cells
  Index bad_faces = 0;  // faces still beyond the limits after the last round
};

// Joins faces and merges cells of `mesh` (cell_size: the edge of each cell's leaf, kept in step). A merged
// cell keeps the larger cell's size. face_geometry is set to the result's (face_geometry of
// each face), which the merging has computed.
AgglomerationStats agglomerate(PolyMesh& mesh, std::vector<double>& cell_size,
                               const AgglomerationOptions& options, std::vector<FaceGeometry>& face_geometry);

}  // namespace volmesh::cutcell
