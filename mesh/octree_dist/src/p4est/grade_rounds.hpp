#pragma once
// build_octree's buffer layers between levels (grade(), --cells-between-levels) on the
// forest. A leaf's buffer reaches cells_between_levels - 1 cells of its level, further than
// any ghost layer of one leaf: each rank sends the centres of the buffer cells its leaves
// ask for to the ranks whose stretch of the curve holds them, which split their leaves there.
#include "forest.hpp"

namespace volmesh::octree_dist {

// From the deepest level down, as grade(): the cells of level l within reach of a leaf of
// level l or finer are refined to level l, balanced. Throws InputError below 1. Returns the
// levels at which something was split.
int grade_rounds(p8est_t* forest, int cells_between_levels);

}  // namespace volmesh::octree_dist
