#pragma once
// A scalar field sampled on a regular grid, such as the signed-distance voxels `volmesh sdf`
// writes: positive inside, negative outside, as in the hex paper. Plain data: io reads and
// writes it (voxel_grid_io.hpp), the grid domain interpolates it.
#include <array>
#include <cstdint>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh {

struct VoxelGrid {
  std::array<Index, 3> dims{};  // samples along x, y, z, each >= 2
  Vec3 origin = Vec3::Zero();   // position of sample (0, 0, 0)
  Vec3 spacing = Vec3::Ones();  // distance between neighbouring samples, > 0
  std::vector<float> values;    // x fastest, finite

  std::int64_t index(Index i, Index j, Index k) const {
    return i + static_cast<std::int64_t>(dims[0]) * (j + static_cast<std::int64_t>(dims[1]) * k);
  }
  float at(Index i, Index j, Index k) const { return values[index(i, j, k)]; }
  Vec3 point(Index i, Index j, Index k) const {
    return origin + spacing.cwiseProduct(Vec3(i, j, k));
  }
};

}  // namespace volmesh
