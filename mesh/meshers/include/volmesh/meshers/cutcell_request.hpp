#pragma once
// The cut-cell method's options from a request: its octree and its own options (the serial
// mesher's and the ranks' pieces read them alike).
#include "volmesh/cutcell/cutcell.hpp"
#include "volmesh/meshers/registry.hpp"

namespace volmesh::meshers {

CutcellOptions cutcell_request(const MeshRequest& request);

}  // namespace volmesh::meshers
