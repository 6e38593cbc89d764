// Whether the build has p4est; without it, the refusals.
#include "volmesh/core/errors.hpp"
#include "volmesh/octree_dist/cutcell_piece.hpp"
#include "volmesh/octree_dist/distributed_octree.hpp"
#include "volmesh/octree_dist/grid_piece.hpp"
#include "volmesh/octree_dist/staircase_piece.hpp"

#ifdef VOLMESH_HAVE_P4EST
#include <p4est_config.h>
#endif

namespace volmesh {

#ifdef VOLMESH_HAVE_P4EST

bool p4est_built() { return true; }

std::string distributed_octree_summary() {
  return std::string("distributed octree: p4est ") + P4EST_VERSION;
}

#else

bool p4est_built() { return false; }

std::string distributed_octree_summary() { return "distributed octree: built without p4est"; }

DistributedOctree build_distributed_octree(const Domain&, const OctreeOptions&, int) {
  throw InputError("this volmesh was built without p4est: no distributed octree");
}

RankPiece staircase_piece(const DistributedOctree&, const Domain&) {
  throw InputError("this volmesh was built without p4est: no distributed octree");
}

RankPiece cutcell_piece(const Domain&, const CutcellOptions&) {
  throw InputError("this volmesh was built without p4est: no distributed octree");
}

RankPiece grid_piece(const Box3&, int) {
  throw InputError("this volmesh was built without p4est: no distributed grid");
}

#endif

}  // namespace volmesh
