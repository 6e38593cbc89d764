#pragma once
// The vertex table without the region queries (the staircase mesher classifies cell centres,
// not vertices).
#include "volmesh/octree/octree.hpp"

namespace volmesh {

OctreeVertices octree_vertex_geometry(const Octree& tree);

}  // namespace volmesh
