#pragma once
// Smoothing (Stellar's family 1): a point moves to raise the worst quality of its star.
#include "tet_complex.hpp"

namespace volmesh::improve {

// Moves free point v, or sliding point v within its triangle or edge, where its star's worst
// quality is higher, if there is such a place with every tet positive by the exact test.
// Returns whether it moved.
bool smooth_point(TetComplex& mesh, Index v);

}  // namespace volmesh::improve
