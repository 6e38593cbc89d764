#pragma once
// Sampled signed-distance fields (positive inside) shared by the hexdc tests.
#include <algorithm>
#include <cmath>
#include <functional>

#include "volmesh/core/voxel_grid.hpp"

namespace volmesh::test_fields {

// dim^3 samples of f from `origin`, `spacing` apart.
inline VoxelGrid sample(Index dim, const Vec3& origin, double spacing,
                        const std::function<double(const Vec3&)>& f) {
  VoxelGrid g;
  g.dims = {dim, dim, dim};
  g.origin = origin;
  g.spacing = Vec3::Constant(spacing);
  g.values.resize(static_cast<std::size_t>(dim) * dim * dim);
  for (Index k = 0; k < dim; ++k)
    for (Index j = 0; j < dim; ++j)
      for (Index i = 0; i < dim; ++i)
        g.values[static_cast<std::size_t>(g.index(i, j, k))] =
            static_cast<float>(f(g.point(i, j, k)));
  return g;
}

// 65^3 samples over [-1, 1]^3, as the paper's examples: k = 6.
inline constexpr Index kPaperDim = 65;

inline VoxelGrid sample_paper_cube(const std::function<double(const Vec3&)>& f) {
  return sample(kPaperDim, Vec3::Constant(-1.0), 2.0 / (kPaperDim - 1), f);
}

// A torus about z with radii 0.6 and 0.25.
inline double torus_distance(const Vec3& p) {
  return 0.25 - std::hypot(std::hypot(p.x(), p.y()) - 0.6, p.z());
}

// The box [-kBoxHalfSide, kBoxHalfSide]^3, its sides off the paper cube's samples.
inline constexpr double kBoxHalfSide = 0.55;

inline double box_distance(const Vec3& p) {
  const Vec3 d = p.cwiseAbs() - Vec3::Constant(kBoxHalfSide);
  return -(d.cwiseMax(0.0).norm() + std::min(d.maxCoeff(), 0.0));
}

// The closest point of the box's surface: clamped outside; inside, onto the nearest face.
inline Vec3 closest_on_box(const Vec3& p) {
  const Vec3 clamped = p.cwiseMax(-kBoxHalfSide).cwiseMin(kBoxHalfSide);
  if (clamped != p) return clamped;
  int axis = 0;
  const Vec3 depth = Vec3::Constant(kBoxHalfSide) - p.cwiseAbs();
  depth.minCoeff(&axis);
  Vec3 q = p;
  q[axis] = std::copysign(kBoxHalfSide, p[axis]);
  return q;
}

}  // namespace volmesh::test_fields
