#pragma once
// Sampled signed-distance fields (positive inside) shared by the hexdc tests.
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

}  // namespace volmesh::test_fields
