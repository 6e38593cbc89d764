#pragma once
// Smoothing of one interior node: moved where the minimum quality of its incident tets (its
// star) rises, and only if every tet of the star stays positive by the exact orientation test.
// The star's outer faces do not move, so a positive star still fills the same polyhedron.
#include "live_mesh.hpp"

namespace volmesh::tet::front {

// Tries the centroid of the node's neighbours (smart Laplacian), then a few steps of max-min
// ascent: along the gradient of each of the worst tets' qualities and of their sum, with a
// backtracking line search, the best point kept. Returns whether the node moved.
bool smooth_node(LiveMesh& mesh, Index v);

}  // namespace volmesh::tet::front
