#pragma once
// Closing a stalled front: the cavity it bounds becomes one tet, a fan from a point that sees
// all of it, or else the projection mesher's tets (projection.hpp, rounding.hpp), merged in
// even where they split the cavity's faces: the tets outside are refined to match (merge.hpp).
#include <vector>

#include "merge.hpp"
#include "volmesh/core/element_mesh.hpp"
#include "volmesh/tet_front/front.hpp"

namespace volmesh::tet::front {

// Appends to `mesh` (points, cells, cell_region) the tets, labelled `label`, that fill the
// cavity bounded by `faces` (each facing into it, current: resolved through `splits`), and
// refines the tets around it to stay conforming. `loose` are the faces of no tet that a split
// may cut (boundary triangles, other cavities' faces): those cut are recorded in `splits`.
// Throws InputError when no projection direction gives tets that stay positive in doubles.
void close_cavity(TetMesh& mesh, Index label, const std::vector<Tri>& faces,
                  const std::vector<Tri>& loose, FaceSplits& splits, FrontStats& stats);

}  // namespace volmesh::tet::front
