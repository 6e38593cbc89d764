#pragma once
// The field's measures of thinness and curvature over a box of samples (refine_thin.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "volmesh/core/voxel_grid.hpp"

namespace volmesh::hexdc_detail {

// A closed box of sample indices.
struct SampleBox {
  std::array<Index, 3> lo{}, hi{};
};

inline constexpr double kNoWidth = std::numeric_limits<double>::infinity();

struct SurfaceMeasures {
  // The shortest way across the solid from a crossing of the box's voxel edges, inward along
  // the field's normal there to where the field turns negative again; kNoWidth beyond the cap.
  double width = kNoWidth;
  // The largest angle (degrees) between the normals at those crossings and their mean; 0 with
  // fewer than two crossings.
  double spread_deg = 0.0;
};

// The measures of the surface crossing `box`, widths followed as far as `cap` (length units).
SurfaceMeasures surface_measures(const VoxelGrid& field, const SampleBox& box, double cap);

// The samples covering the bounding box of `corners`, clamped to the grid.
template <typename Points>
SampleBox sample_box(const VoxelGrid& field, const Points& corners) {
  SampleBox box;
  for (std::size_t a = 0; a < 3; ++a) {
    const auto axis = static_cast<Eigen::Index>(a);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : corners) {
      lo = std::min(lo, (p[axis] - field.origin[axis]) / field.spacing[axis]);
      hi = std::max(hi, (p[axis] - field.origin[axis]) / field.spacing[axis]);
    }
    const Index last = field.dims[a] - 1;
    box.lo[a] = std::clamp(static_cast<Index>(std::floor(lo)), Index{0}, last);
    box.hi[a] = std::clamp(static_cast<Index>(std::ceil(hi)), Index{0}, last);
  }
  return box;
}

}  // namespace volmesh::hexdc_detail
