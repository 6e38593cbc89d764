// build_octree's stages on the forest, in build_octree's order (each stage's result depends
// on the tree it starts from): the uniform base level, the domain's boundaries and
// interfaces, the box and surface fronts, the buffer layers; then the partition weighted
// by cut leaves and the ghost layer.
#include <mpi.h>
#include <p8est_ghost.h>

#include <algorithm>
#include <string>

#include "forest.hpp"
#include "grade_rounds.hpp"
#include "refine_stages.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/octree_dist/distributed_octree.hpp"

namespace volmesh {
namespace {

using namespace octree_dist;

void check_level(int level) {
  if (level > kDistributedOctreeMaxLevel)
    throw InputError("--level " + std::to_string(level) + " exceeds the distributed octree's maximum " +
                     std::to_string(kDistributedOctreeMaxLevel) + " (p4est's)");
  if (level < 0) throw InputError("--level " + std::to_string(level) + " is negative");
}

void check_options(const OctreeOptions& options) {
  check_level(options.level);
  if (options.level == 0)
    throw InputError("--level 0: the domain is smaller than one cell (the root cube); use a level of at least 1");
  for (const BoxFront& f : options.boxes) check_level(f.level);
  for (const SurfaceFront& f : options.surfaces) {
    check_level(f.level);
    if (!f.surface) throw InputError("octree: a surface front without a surface");
  }
  if (options.cells_between_levels < 1) throw InputError("--cells-between-levels must be at least 1");
  int started = 0;
  MPI_Initialized(&started);
  if (!started) throw InputError("the distributed octree needs MPI started (run under mpirun)");
}

int weigh_by_cut(p8est_t*, p4est_topidx_t, p8est_quadrant_t* q) {
  return leaf_data(*q).state == LeafState::cut ? kCutLeafWeight : 1;
}

void collect_leaves(p8est_t* forest, DistributedOctree& out) {
  out.leaves.reserve(forest->local_num_quadrants);
  out.cut.reserve(forest->local_num_quadrants);
  for_each_leaf(forest, [&out](p8est_quadrant_t& q) {
    out.leaves.push_back(to_leaf(q));
    out.cut.push_back(leaf_data(q).state == LeafState::cut);
  });
}

void collect_ghosts(p8est_t* forest, int layers, DistributedOctree& out) {
  p8est_ghost_t* ghost = p8est_ghost_new(forest, P8EST_CONNECT_FULL);
  for (int layer = 1; layer < layers; ++layer) p8est_ghost_expand(forest, ghost);
  const std::size_t n = ghost->ghosts.elem_count;
  out.ghosts.reserve(n);
  out.ghost_owner.reserve(n);
  // Ghosts are sorted by owner, then in Morton order: by the curve, since owners follow it.
  for (int r = 0; r < forest->mpisize; ++r)
    for (p4est_locidx_t i = ghost->proc_offsets[r]; i < ghost->proc_offsets[r + 1]; ++i) {
      out.ghosts.push_back(to_leaf(*p8est_quadrant_array_index(&ghost->ghosts, i)));
      out.ghost_owner.push_back(r);
    }
  p8est_ghost_destroy(ghost);
}

}  // namespace

DistributedOctree build_distributed_octree(const Domain& domain, const OctreeOptions& options, int ghost_layers) {
  const Clock::time_point start = Clock::now();
  check_options(options);
  if (ghost_layers < 1) throw InputError("the distributed octree needs at least one ghost layer");
  DistributedOctree out;
  out.root = octree_root(domain, options);
  const Octree frame(out.root.origin, out.root.side);

  Forest forest(std::max(std::min(options.base_level, options.level), 0));
  p8est_t* p = forest.get();
  DistributedOctreeStats& st = out.stats;
  {
    InterfaceQuery query(frame, domain);
    st.refinement_rounds += refine_toward_interfaces(p, query, options.level);
  }
  for (const BoxFront& f : options.boxes) st.refinement_rounds += refine_into_box(p, frame, f);
  for (const SurfaceFront& f : options.surfaces) {
    forget_states(p);
    InterfaceQuery front(frame, *f.surface);
    st.refinement_rounds += refine_toward_interfaces(p, front, f.level);
  }
  if (!options.surfaces.empty()) forget_states(p);
  st.graded_levels = grade_rounds(p, options.cells_between_levels);

  classify_leaves(p, frame, domain);
  p8est_partition(p, 0, weigh_by_cut);
  out.rank = p->mpirank;
  out.ranks = p->mpisize;
  out.global_leaves = p->global_num_quadrants;
  collect_leaves(p, out);
  collect_ghosts(p, ghost_layers, out);
  st.seconds = seconds_since(start);
  return out;
}

}  // namespace volmesh
