#pragma once
// The cut-cell mesher on an octree given whole: the stages of cutcell_mesh after the octree
// (the extra refinement rules, the vertex moves, M3S and M3C, the merging). A rank's window
// of a distributed octree (its leaves, ghost layers and coarse fillers) meshes this way.
#include "volmesh/cutcell/cutcell.hpp"

namespace volmesh {

// `tree` must be 2:1 balanced across faces and edges and tile its root (build_octree's, or
// balance()'s). options.octree.level is the level of the extra rules. Throws as cutcell_mesh.
PolyMesh cutcell_mesh_of_tree(Octree tree, const Domain& domain, const CutcellOptions& options,
                              CutcellStats* stats = nullptr);

}  // namespace volmesh
