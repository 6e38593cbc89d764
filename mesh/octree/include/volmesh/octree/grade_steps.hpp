#pragma once
// grade()'s two steps at one level l (octree.hpp), also run on each rank's stretch of a
// distributed octree's leaves.
#include <cstdint>
#include <span>
#include <vector>

#include "volmesh/octree/octree.hpp"

namespace volmesh {

// The level-l cells (by the Morton code of their anchor) that leaves of level l or finer
// cover, sorted; the leaves in Morton order.
std::vector<std::uint64_t> grade_covered_cells(std::span<const OctreeLeaf> leaves, int level);
// The centres of the level-l cells within `reach` cells of a covered one (a box of
// 2 reach + 1 cells around it) and not covered themselves, in Morton order: the buffer to
// refine.
std::vector<GridPoint> grade_buffer_centres(const std::vector<std::uint64_t>& covered, int level, int reach);

}  // namespace volmesh
