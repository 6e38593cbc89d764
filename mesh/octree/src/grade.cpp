// Buffer layers between levels (snappyHexMesh's nCellsBetweenLevels): the region refined to
// level l or finer grows by N - 1 cells of level l, from the finest level down, so that each
// level spans at least N cells across before the next coarser one begins (N = 1: the 2:1
// balance alone).
#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_sort.h>

#include <algorithm>
#include <vector>

#include "volmesh/core/errors.hpp"
#include "volmesh/octree/grade_steps.hpp"
#include "volmesh/octree/key_map.hpp"
#include "volmesh/octree/octree.hpp"

namespace volmesh {

std::vector<std::uint64_t> grade_covered_cells(std::span<const OctreeLeaf> leaves, int level) {
  const std::uint32_t mask = ~((kOctreeGrid >> level) - 1);
  std::vector<std::uint64_t> cells;
  for (const OctreeLeaf& leaf : leaves)
    if (leaf.level >= level)
      cells.push_back(morton_encode({leaf.anchor[0] & mask, leaf.anchor[1] & mask, leaf.anchor[2] & mask}));
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());  // Morton order already
  return cells;
}

std::vector<GridPoint> grade_buffer_centres(const std::vector<std::uint64_t>& covered, int level, int reach) {
  const std::int64_t size = kOctreeGrid >> level;
  KeyMap is_covered(covered.size());  // one probe per neighbour instead of a binary search
  for (const std::uint64_t c : covered) is_covered.insert(c, 0);
  tbb::enumerable_thread_specific<std::vector<GridPoint>> found;
  tbb::parallel_for(std::size_t{0}, covered.size(), [&](std::size_t i) {
    const GridPoint a = morton_decode(covered[i]);
    auto& out = found.local();
    for (int dz = -reach; dz <= reach; ++dz)
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx) {
          const std::array<std::int64_t, 3> q{a[0] + dx * size, a[1] + dy * size, a[2] + dz * size};
          if (std::any_of(q.begin(), q.end(), [](std::int64_t c) { return c < 0 || c >= kOctreeGrid; }))
            continue;
          const GridPoint cell{static_cast<std::uint32_t>(q[0]), static_cast<std::uint32_t>(q[1]),
                               static_cast<std::uint32_t>(q[2])};
          if (is_covered.find(morton_encode(cell)) != kNoIndex) continue;
          const std::uint32_t h = static_cast<std::uint32_t>(size / 2);
          out.push_back({cell[0] + h, cell[1] + h, cell[2] + h});
        }
  });
  std::vector<std::uint64_t> codes;
  for (const auto& part : found)
    for (const GridPoint& p : part) codes.push_back(morton_encode(p));
  tbb::parallel_sort(codes.begin(), codes.end());
  codes.erase(std::unique(codes.begin(), codes.end()), codes.end());
  std::vector<GridPoint> centres(codes.size());
  for (std::size_t i = 0; i < codes.size(); ++i) centres[i] = morton_decode(codes[i]);
  return centres;
}

void grade(Octree& tree, int cells_between_levels) {
  if (cells_between_levels < 1)
    throw InputError("--cells-between-levels must be at least 1");
  const int reach = cells_between_levels - 1;
  if (reach == 0) return;
  for (int level = tree.max_leaf_level(); level >= 2; --level) {
    // The buffer is fixed before splitting: leaves it creates do not widen it in turn. A
    // centre once in a leaf of the level stays so (splits only refine): it is dropped.
    std::vector<GridPoint> centres = grade_buffer_centres(grade_covered_cells(tree.leaves(), level), level, reach);
    while (!centres.empty()) {
      std::vector<Index> coarse;
      std::vector<GridPoint> pending;
      for (const GridPoint& p : centres) {
        const Index leaf = tree.leaf_containing(p);
        if (tree.leaf(leaf).level >= level) continue;
        coarse.push_back(leaf);
        pending.push_back(p);
      }
      std::sort(coarse.begin(), coarse.end());
      coarse.erase(std::unique(coarse.begin(), coarse.end()), coarse.end());
      if (!coarse.empty()) split_balanced(tree, std::move(coarse));
      centres = std::move(pending);
    }
  }
}

}  // namespace volmesh
