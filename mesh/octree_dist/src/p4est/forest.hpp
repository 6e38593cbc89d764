#pragma once
// The p4est forest behind a distributed octree: one tree, the unit cube, whose integer grid
// maps onto the serial octree's root cube; what each leaf carries; the refine and balance
// rounds every stage runs.
#include <p8est.h>
#include <p8est_extended.h>

#include <cstdint>

#include "volmesh/octree/octree.hpp"

namespace volmesh::octree_dist {

// p4est's root is 2^19 long, the serial octree's 2^20: a p4est coordinate is half the
// octree's grid coordinate of the same point.
inline constexpr std::uint32_t kGridPerP4est = kOctreeGrid / P8EST_ROOT_LEN;
static_assert(kGridPerP4est * P8EST_ROOT_LEN == kOctreeGrid);

// What the domain's interface criterion said of a leaf, for the domain of the current stage.
enum class LeafState : std::uint8_t { unknown, uncut, cut };
struct LeafData {
  LeafState state;
};
inline LeafData& leaf_data(p8est_quadrant_t& q) { return *static_cast<LeafData*>(q.p.user_data); }

OctreeLeaf to_leaf(const p8est_quadrant_t& q);
// The p4est quadrant of the finest level whose anchor is p (octree grid coordinates, even).
p8est_quadrant_t finest_quadrant(const GridPoint& p);

// p4est's init callback: a new leaf's state is unknown.
void init_leaf(p8est_t*, p4est_topidx_t, p8est_quadrant_t* q);

// A forest on MPI_COMM_WORLD refined uniformly to base_level, every leaf's state unknown.
// Starts sc and p4est (quietly) the first time.
class Forest {
 public:
  explicit Forest(int base_level);
  ~Forest();
  Forest(const Forest&) = delete;
  Forest& operator=(const Forest&) = delete;
  p8est_t* get() const { return forest_; }

 private:
  p8est_connectivity_t* connectivity_;
  p8est_t* forest_;
};

// Calls f(quadrant) on each of this rank's leaves, in Morton order.
template <class F>
void for_each_leaf(p8est_t* forest, F&& f) {
  p8est_tree_t* tree = p8est_tree_array_index(forest->trees, 0);
  for (std::size_t i = 0; i < tree->quadrants.elem_count; ++i) f(*p8est_quadrant_array_index(&tree->quadrants, i));
}

// Rounds of p8est_refine (recursive, refine_fn seeing `context` as the forest's user
// pointer) and p8est_balance across faces and edges, until a refinement leaves the forest as
// it was: the coarsest balanced refinement in which refine_fn selects no leaf. The forest
// must come in balanced. Returns the rounds that split leaves.
int refine_until_stable(p8est_t* forest, p8est_refine_t refine_fn, void* context);

// Every leaf's state back to unknown (for a stage with another domain).
void forget_states(p8est_t* forest);

}  // namespace volmesh::octree_dist
