#pragma once
// Signed-distance voxels from a closed surface (`volmesh sdf`, as the hex paper's
// dual-contouring mesher takes them): SD(p) = S(p) D(p), D the exact distance to the nearest
// triangle, S = +1 inside, -1 outside (the paper's convention). The sign comes from the
// angle-weighted pseudo-normal of the nearest face, edge or vertex (Bærentzen & Aanæs 2005),
// which is right for a closed, manifold surface; near a self-intersection it may not be.
#include <functional>
#include <memory>
#include <string>

#include "volmesh/core/tri_surface.hpp"
#include "volmesh/core/voxel_grid.hpp"
#include "volmesh/domain/domain.hpp"  // Box3

namespace volmesh {

namespace surface {
struct DistanceData;
}

// True for 2^k + 1, k >= 1: the sample counts an octree over the grid needs.
bool is_octree_dim(Index dim);

// The cubic grid of dim^3 samples (dim = 2^k + 1) centred on `box`, whose side is the box's
// largest side grown by `margin` times it on each end. Origin and spacing are rounded to
// float, as .rawiv stores them, so that the file describes the samples exactly. No values.
// Throws std::invalid_argument for another dim, a negative margin or an empty box.
VoxelGrid sdf_layout(const Box3& box, Index dim, double margin);

class SignedDistance {
 public:
  // Throws InputError "NAME: ..." as a SurfaceDomain does (surface.hpp).
  SignedDistance(TriSurface surface, const std::string& name);
  ~SignedDistance();
  SignedDistance(SignedDistance&&) noexcept;
  SignedDistance& operator=(SignedDistance&&) noexcept;

  // Exact up to the rounding of the point-triangle distance (an absolute error of about
  // 1e-16 of the coordinates' magnitude).
  double operator()(const Vec3& p) const;
  // The closest point of the triangles to p, exact as operator() is.
  Vec3 closest_point(const Vec3& p) const;
  Box3 bounds() const;  // of the triangles

  // Fills grid.values from dims, origin and spacing, on every core. The values depend only
  // on the grid, not on the thread count or the scheduling. `progress`, if given, is called
  // with the fraction done (in (0, 1], increasing), one call at a time, from any thread.
  void sample(VoxelGrid& grid, const std::function<void(double)>& progress = {}) const;
  // As sample(), exact only within `band` of the surface: the grid goes in bricks, and a
  // brick whose centre is farther than `band` plus the brick's half-diagonal from the surface
  // takes, at each sample, the sign of its centre and the bound |SD(centre)| - |p - centre|
  // (the distance is 1-Lipschitz), which is below the exact |SD(p)| and above `band`. Signs
  // are exact everywhere and values within `band`, as sample()'s; far from the surface the
  // work is one query per brick.
  void sample_band(VoxelGrid& grid, double band,
                   const std::function<void(double)>& progress = {}) const;

 private:
  std::unique_ptr<const surface::DistanceData> data_;
};

}  // namespace volmesh
