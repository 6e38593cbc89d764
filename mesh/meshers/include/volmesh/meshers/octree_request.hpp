#pragma once
// What the octree methods share: their OctreeOptions from a request, and the mesh size.
#include "volmesh/meshers/registry.hpp"
#include "volmesh/octree/octree.hpp"

namespace volmesh::meshers {

// OctreeOptions with the request's level, the shared octree options given, and the base
// level raised to the level when the request is uniform.
OctreeOptions octree_request(const MeshRequest& request);

// The edge of a leaf at options.level: the root cube's side / 2^level.
double octree_cell_size(const Domain& domain, const OctreeOptions& options);

}  // namespace volmesh::meshers
