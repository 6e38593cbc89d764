#pragma once
// Vertex insertion (Stellar's family 3): a point inside a bad tet, the cavity around it
// re-tetrahedralised as a cone from the point, the point then smoothed.
#include "tet_complex.hpp"

namespace volmesh::improve {

// Inserts a point in tet t when that raises the worst quality of the tets it replaces;
// returns whether it did.
bool insert_point(TetComplex& mesh, Index t);

}  // namespace volmesh::improve
