#pragma once
// A labelled image (a segmentation): one region label per voxel, 0 being outside. Plain
// data: io reads and writes it (label_image_io.hpp), the image domain queries it.
#include <array>
#include <cstdint>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh {

// Voxel (i, j, k) is the box of size `spacing` centred at origin + (i, j, k) * spacing, and
// the image is constant on each voxel.
struct LabelImage {
  std::array<Index, 3> dims{};       // voxels along x, y, z
  Vec3 spacing = Vec3::Ones();       // voxel size, > 0
  Vec3 origin = Vec3::Zero();        // centre of voxel (0, 0, 0)
  std::vector<Index> labels;         // 0, then the other labels that occur, ascending
  std::vector<std::uint16_t> codes;  // per voxel, x fastest: the position of its label in `labels`

  std::int64_t index(Index i, Index j, Index k) const {
    return i + static_cast<std::int64_t>(dims[0]) * (j + static_cast<std::int64_t>(dims[1]) * k);
  }
  Index label(Index i, Index j, Index k) const { return labels[codes[index(i, j, k)]]; }
};

}  // namespace volmesh
