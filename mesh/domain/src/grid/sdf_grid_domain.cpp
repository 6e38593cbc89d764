// Signed-distance grid as a Domain: regions, field, normals (crossings in
// sdf_grid_crossings.cpp).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "volmesh/domain/grid.hpp"
#include "voxel_trilinear.hpp"

namespace volmesh {

SdfGridDomain::SdfGridDomain(VoxelGrid grid) : grid_(std::move(grid)) {
  const auto& n = grid_.dims;
  if (n[0] < 2 || n[1] < 2 || n[2] < 2 || !(grid_.spacing.minCoeff() > 0.0) ||
      !grid_.spacing.allFinite() || !grid_.origin.allFinite() ||
      static_cast<std::int64_t>(grid_.values.size()) !=
          static_cast<std::int64_t>(n[0]) * n[1] * n[2] ||
      !std::all_of(grid_.values.begin(), grid_.values.end(),
                   [](float v) { return std::isfinite(v); }))
    throw std::invalid_argument(
        "SdfGridDomain: inconsistent VoxelGrid (dims >= 2, spacing > 0, finite values)");
  inv_spacing_ = grid_.spacing.cwiseInverse();
  hi_ = grid_.point(n[0] - 1, n[1] - 1, n[2] - 1);
  for (int c = 0; c < 8; ++c) offsets_[c] = grid_.index(c & 1, (c >> 1) & 1, (c >> 2) & 1);

  // Every point with f >= 0 is in a cell with a corner >= 0 (f interpolates convexly).
  std::array<Index, 3> first = n, last{-1, -1, -1};
  for (Index k = 0; k < n[2]; ++k)
    for (Index j = 0; j < n[1]; ++j)
      for (Index i = 0; i < n[0]; ++i)
        if (grid_.at(i, j, k) >= 0.0f) {
          first = {std::min(first[0], i), std::min(first[1], j), std::min(first[2], k)};
          last = {std::max(last[0], i), std::max(last[1], j), std::max(last[2], k)};
        }
  empty_ = last[0] < 0;
  if (empty_) {
    bounds_ = {grid_.origin, hi_};
    return;
  }
  const auto grown = [&](Index i, Index j, Index k) {
    return grid_.point(std::clamp(i, 0, n[0] - 1), std::clamp(j, 0, n[1] - 1),
                       std::clamp(k, 0, n[2] - 1));
  };
  bounds_ = {grown(first[0] - 1, first[1] - 1, first[2] - 1),
             grown(last[0] + 1, last[1] + 1, last[2] + 1)};
}

std::int64_t SdfGridDomain::locate(const Vec3& p, Vec3& f) const {
  const Vec3 u = (p.cwiseMax(grid_.origin).cwiseMin(hi_) - grid_.origin).cwiseProduct(inv_spacing_);
  std::array<Index, 3> cell;
  for (int m = 0; m < 3; ++m) {
    cell[m] = std::min(static_cast<Index>(u[m]), grid_.dims[m] - 2);
    f[m] = u[m] - cell[m];
  }
  return grid_.index(cell[0], cell[1], cell[2]);
}

std::array<double, 8> SdfGridDomain::corners(std::int64_t base) const {
  std::array<double, 8> c;
  for (int i = 0; i < 8; ++i) c[i] = grid_.values[base + offsets_[i]];
  return c;
}

Index SdfGridDomain::region(const Vec3& p) const {
  if (!(p.x() >= grid_.origin.x() && p.y() >= grid_.origin.y() && p.z() >= grid_.origin.z() &&
        p.x() <= hi_.x() && p.y() <= hi_.y() && p.z() <= hi_.z()))
    return 0;  // outside the grid (or NaN)
  Vec3 f;
  const std::int64_t base = locate(p, f);
  return voxel::trilinear(corners(base), f) >= 0.0 ? 1 : 0;
}

double SdfGridDomain::value(const Vec3& p) const {
  Vec3 f;
  const std::int64_t base = locate(p, f);
  return voxel::trilinear(corners(base), f);
}

// Central differences, one-sided on the box faces.
Vec3 SdfGridDomain::node_gradient(Index i, Index j, Index k) const {
  const std::array<Index, 3> at{i, j, k};
  Vec3 g;
  for (int m = 0; m < 3; ++m) {
    std::array<Index, 3> lo = at, hi = at;
    lo[m] = std::max(at[m] - 1, 0);
    hi[m] = std::min(at[m] + 1, grid_.dims[m] - 1);
    g[m] = (double{grid_.at(hi[0], hi[1], hi[2])} - grid_.at(lo[0], lo[1], lo[2])) /
           ((hi[m] - lo[m]) * grid_.spacing[m]);
  }
  return g;
}

Vec3 SdfGridDomain::gradient(const Vec3& p) const {
  Vec3 f;
  const std::int64_t base = locate(p, f);
  const Index i = static_cast<Index>(base % grid_.dims[0]),
              j = static_cast<Index>(base / grid_.dims[0] % grid_.dims[1]),
              k = static_cast<Index>(base / grid_.dims[0] / grid_.dims[1]);
  std::array<std::array<double, 8>, 3> c;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 g =
        node_gradient(i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1));
    for (int m = 0; m < 3; ++m) c[m][corner] = g[m];
  }
  return {voxel::trilinear(c[0], f), voxel::trilinear(c[1], f), voxel::trilinear(c[2], f)};
}

Vec3 SdfGridDomain::normal(const Vec3& p) const {
  const Vec3 g = gradient(p);
  return g.norm() > 0.0 ? Vec3(-g.normalized()) : Vec3::UnitZ();
}

Box3 SdfGridDomain::bounds() const { return bounds_; }

std::vector<Index> SdfGridDomain::regions() const {
  return empty_ ? std::vector<Index>{} : std::vector<Index>{1};
}

}  // namespace volmesh
