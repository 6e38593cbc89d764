#include "forest.hpp"

#include <mpi.h>
#include <sc.h>

namespace volmesh::octree_dist {

OctreeLeaf to_leaf(const p8est_quadrant_t& q) {
  return {{static_cast<std::uint32_t>(q.x) * kGridPerP4est, static_cast<std::uint32_t>(q.y) * kGridPerP4est,
           static_cast<std::uint32_t>(q.z) * kGridPerP4est},
          q.level};
}

p8est_quadrant_t finest_quadrant(const GridPoint& p) {
  p8est_quadrant_t q{};
  q.x = static_cast<p4est_qcoord_t>(p[0] / kGridPerP4est);
  q.y = static_cast<p4est_qcoord_t>(p[1] / kGridPerP4est);
  q.z = static_cast<p4est_qcoord_t>(p[2] / kGridPerP4est);
  q.level = P8EST_QMAXLEVEL;
  return q;
}

void init_leaf(p8est_t*, p4est_topidx_t, p8est_quadrant_t* q) { leaf_data(*q).state = LeafState::unknown; }

namespace {

// sc and p4est log nothing below errors: progress is volmesh's to report.
void start_p4est() {
  static const bool started = [] {
    sc_init(MPI_COMM_WORLD, 0, 0, nullptr, SC_LP_ERROR);
    p4est_init(nullptr, SC_LP_ERROR);
    return true;
  }();
  (void)started;
}

}  // namespace

Forest::Forest(int base_level) {
  start_p4est();
  connectivity_ = p8est_connectivity_new_unitcube();
  forest_ = p8est_new_ext(MPI_COMM_WORLD, connectivity_, 0, base_level, 1, sizeof(LeafData), init_leaf, nullptr);
}

Forest::~Forest() {
  p8est_destroy(forest_);
  p8est_connectivity_destroy(connectivity_);
}

int refine_until_stable(p8est_t* forest, p8est_refine_t refine_fn, void* context) {
  forest->user_pointer = context;
  int rounds = 0;
  for (;;) {
    const p4est_gloidx_t before = forest->global_num_quadrants;
    p8est_refine(forest, 1, refine_fn, init_leaf);
    // A forest the refinement left as it was is still balanced (as it came in, or from the
    // round before): its balance would be a pass over every leaf for nothing.
    if (forest->global_num_quadrants == before) break;
    p8est_balance(forest, P8EST_CONNECT_EDGE, init_leaf);
    ++rounds;
  }
  forest->user_pointer = nullptr;
  return rounds;
}

void forget_states(p8est_t* forest) {
  for_each_leaf(forest, [](p8est_quadrant_t& q) { leaf_data(q).state = LeafState::unknown; });
}

}  // namespace volmesh::octree_dist
