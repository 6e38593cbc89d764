#pragma once
// A scalar grid's field as a Domain: signed-distance voxels (VoxelGrid, core/voxel_grid.hpp,
// as `volmesh sdf` writes them), positive inside, negative outside, as in the hex paper.
#include <array>
#include <cstdint>

#include "volmesh/core/voxel_grid.hpp"
#include "volmesh/domain/domain.hpp"

namespace volmesh {

// The grid's field f as a Domain, f being the trilinear interpolant of the samples on the
// grid's box (region 0 outside the box).
//  - region(p) = 1 where f(p) >= 0: a point on the zero level set is inside, as in the hex
//    paper (its nodes with F >= 0 are inside) and as the Domain contract gives points on an
//    interface the solid's region. 0 where f < 0.
//  - crossings: exact for the interpolant. Along a segment f is a cubic in t inside each cell;
//    every root in every cell the segment passes is found (split into monotone pieces at the
//    critical points, then a bracketed Newton iteration to machine precision). A segment
//    touching the zero set from outside at an exact zero gives one crossing with before ==
//    after == 0 and the outward normal (a tangential touch, as AnalyticDomain reports it);
//    an end point on the zero set gives a crossing at t = 0 or 1 if the segment leaves the
//    solid there. Where the solid reaches the grid's box, the box face is an interface too.
//  - normal(p) = -grad f / |grad f| (outward), grad f from central differences at the nodes
//    (one-sided on the box faces), interpolated trilinearly; +z where it vanishes.
class SdfGridDomain final : public Domain {
 public:
  // Throws std::invalid_argument if the grid is inconsistent (sizes, spacing, non-finite values).
  explicit SdfGridDomain(VoxelGrid grid);

  using Domain::crossings;
  using Domain::region;
  Index region(const Vec3& p) const override;
  std::vector<Crossing> crossings(const Vec3& a, const Vec3& b) const override;
  Vec3 normal(const Vec3& p) const override;
  Box3 bounds() const override;  // nodes with f >= 0, grown by one cell, within the grid's box
  std::vector<Index> regions() const override;

  // f and its gradient at p, clamped into the grid's box.
  double value(const Vec3& p) const;
  Vec3 gradient(const Vec3& p) const;
  const VoxelGrid& grid() const { return grid_; }

 private:
  // The cell holding p (clamped into the box) and p's coordinates within it, in [0, 1].
  std::int64_t locate(const Vec3& p, Vec3& f) const;
  std::array<double, 8> corners(std::int64_t base) const;
  Vec3 node_gradient(Index i, Index j, Index k) const;

  VoxelGrid grid_;
  Vec3 inv_spacing_, hi_;
  std::array<std::int64_t, 8> offsets_;  // from a cell's first node to its corners, x + 2y + 4z
  Box3 bounds_;
  bool empty_ = true;
};

}  // namespace volmesh
