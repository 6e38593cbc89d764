#pragma once
// The isosurface crossings of the voxel edges of one octree node.
#include <array>
#include <vector>

#include "volmesh/core/voxel_grid.hpp"
#include "volmesh/hexdc/qef.hpp"

namespace volmesh {

// The gradient of the field at sample (i, j, k) by central differences, one-sided on the
// grid's faces.
Vec3 field_gradient(const VoxelGrid& field, const std::array<Index, 3>& sample);

// Crossings of every voxel edge of the node whose lowest sample is `lo` and whose side is
// `size` voxels, the edges on the node's faces included. An edge crosses where one end is
// >= 0 (inside) and the other < 0; the point and the normal are linear in the field along
// the edge, the normal being the normalised interpolated gradient (zero if that vanishes).
std::vector<EdgeCrossing> node_crossings(const VoxelGrid& field, const std::array<Index, 3>& lo,
                                         Index size);

}  // namespace volmesh
