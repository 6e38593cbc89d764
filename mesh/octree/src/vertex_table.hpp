#pragma once
// The vertex table without the region queries (the staircase mesher classifies cell centres,
// not vertices).
#include "volmesh/octree/octree.hpp"

namespace volmesh {

OctreeVertices octree_vertex_geometry(const Octree& tree);

// The table of `tree` from `known`, that of the tree before some of its leaves were split:
// the known vertices keep their regions, the new ones (listed in `fresh`) get none.
OctreeVertices refined_vertex_geometry(const Octree& tree, const OctreeVertices& known,
                                       std::vector<Index>& fresh);

// Marks vertex `id` at p hanging when it lies inside an edge or a face of a leaf, and records
// it as that leaf's mid-edge or face-centre vertex.
void classify_vertex(const Octree& tree, Index id, const GridPoint& p, OctreeVertices& v);

// Throws InputError when nv vertices exceed the index limit.
void check_vertex_count(std::size_t nv);
// leaf_edge_mid and leaf_face_centre of n leaves, all kNoIndex.
void clear_leaf_midpoints(OctreeVertices& v, std::size_t n);

}  // namespace volmesh
