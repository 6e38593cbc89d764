#pragma once
// The box the grid method meshes, for callers that build its cells themselves (each rank its
// piece under mpirun).
#include "volmesh/domain/domain.hpp"
#include "volmesh/meshers/registry.hpp"

namespace volmesh::meshers {

// The domain's bounding box, once the grid method's checks pass: throws InputError as the
// method does (a level past its limit or below 0, an empty box, a domain that does not fill
// its box).
Box3 grid_box(const Domain& domain, const MeshRequest& request);

}  // namespace volmesh::meshers
