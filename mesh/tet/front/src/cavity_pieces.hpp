#pragma once
// How the projection mesh of a cavity cuts the cavity's faces: its boundary triangles (the
// pieces) are matched to the faces they lie on, and its boundary points to the face edges
// they lie inside, exactly (the projection's rational points).
#include <vector>

#include "merge.hpp"
#include "volmesh/core/element_mesh.hpp"
#include "volmesh/tet/projection.hpp"

namespace volmesh::tet::front {

// The split in the projection's point indices. `faces` are the cavity's faces as seen from
// outside it (the projection's outward surfaces), in the projection's input point indices;
// `cavity` labels the tets kept. Empty when no face is cut.
CavitySplit pieces_of_faces(const ProjectionMesh& exact, const TetMesh& rounded, Index cavity,
                            const std::vector<Tri>& faces);

}  // namespace volmesh::tet::front
