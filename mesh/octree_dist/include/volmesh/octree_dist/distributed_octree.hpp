#pragma once
// The octree of build_octree distributed over the MPI ranks with p4est (docs/distributed.md,
// "The distributed octree"). Each rank holds a contiguous stretch of the Morton curve, its
// leaves, and the ghost layer: the other ranks' leaves that touch its own. Over all ranks the
// leaves are build_octree's for the same domain and options.
//
// No MPI or p4est header here: they stay in the module's .cpp files. A build without p4est
// (or without the PETSc/MPI build it needs) has p4est_built() false and refuses to build one.
#include <cstdint>
#include <string>
#include <vector>

#include "volmesh/domain/domain.hpp"
#include "volmesh/octree/octree.hpp"

namespace volmesh {

// Whether this build has p4est, and the --version line that says so.
bool p4est_built();
std::string distributed_octree_summary();

// p4est's deepest leaf level (P8EST_QMAXLEVEL): its integer grid is one level coarser than
// the serial octree's.
inline constexpr int kDistributedOctreeMaxLevel = 18;

// A cut leaf's weight in the partition, against an uncut leaf's 1: the cut-cell mesher's
// work (M3C, merging) lies almost all in the cut leaves.
inline constexpr int kCutLeafWeight = 8;

struct DistributedOctreeStats {
  int refinement_rounds = 0;  // refine + balance rounds that split leaves, all stages
  int graded_levels = 0;      // levels whose buffer (cells_between_levels) split leaves
  double seconds = 0.0;       // this rank's wall time
};

struct DistributedOctree {
  RootCube root;
  int rank = 0, ranks = 1;
  std::int64_t global_leaves = 0;
  // This rank's leaves, in Morton order; every rank's stretch follows the previous rank's.
  std::vector<OctreeLeaf> leaves;
  // Per leaf: it lies on the domain's boundaries or interfaces (its corners in different
  // regions; or, for a leaf the refinement asked, an edge crossed: build_octree's criterion).
  // The partition weighs such leaves heavier: the meshers do most of their work in them.
  std::vector<std::uint8_t> cut;
  // The other ranks' leaves that share a face, an edge or a corner with one of this rank's,
  // and with ghost_layers > 1 those touching them in turn, layer by layer: in Morton order,
  // and the rank owning each.
  std::vector<OctreeLeaf> ghosts;
  std::vector<int> ghost_owner;
  DistributedOctreeStats stats;
};

// Collective over MPI_COMM_WORLD, which must have started. Throws InputError, alike on every
// rank, where build_octree does, for a level beyond kDistributedOctreeMaxLevel, when MPI has
// not started, and in a build without p4est.
DistributedOctree build_distributed_octree(const Domain& domain, const OctreeOptions& options,
                                           int ghost_layers = 1);

}  // namespace volmesh
