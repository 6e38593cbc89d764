#pragma once
// Topological improvement (Shewchuk, "Two discrete optimization algorithms for the topological
// improvement of tetrahedral meshes"): each change replaces a few tets by others filling the
// same polyhedron, is made only when it raises the minimum quality of the tets involved and
// every new tet is positive by the exact orientation test, and never removes a kept face.
#include "live_mesh.hpp"

namespace volmesh::tet::front {

// Edge removal: the ring of n tets around the interior edge ab is replaced by the 2(n - 2)
// tets of the best triangulation of its link polygon, joined to a and b (found by dynamic
// programming over the polygon's triangulations). n = 3 is the 3-2 flip, n = 4 the 4-4 flip.
// Returns n, or 0 when nothing was changed.
int remove_edge(LiveMesh& mesh, Index a, Index b);

// The 2-3 flip: the two tets sharing face `face` (kTetFaces order) of tet t become three
// around the edge joining their apexes.
bool flip_2_3(LiveMesh& mesh, Index t, int face);

// Edge collapse: the movable node a merges into its neighbour b; the tets holding both go, the
// rest of a's star is joined to b instead. Every new tet positive makes them fill a's star
// exactly (a is interior: every boundary face is kept, so has no movable corner), and the
// chain of their boundary faces is the star's, so kept faces stay faces. a is left with no
// tets (LiveMesh::compact drops it).
bool collapse_edge(LiveMesh& mesh, Index a, Index b);

}  // namespace volmesh::tet::front
