#pragma once
// The auxiliary point array: points r_ijk = origin + step (i, j, k), one bit each (alive or
// deleted). Points outside the region are deleted from the start, so "deleted" means outside
// the region or inside a tet made already.
#include <array>
#include <cstdint>
#include <vector>

#include "volmesh/core/tri_surface.hpp"
#include "volmesh/core/types.hpp"

namespace volmesh::tet::front {

// The grid's bits take at most this much memory: a sixth of the 24 GiB the project's machines
// have, so that the mesh, the fallback and the checks beside it still fit.
inline constexpr double kMaxAuxBytes = 4.0 * 1024 * 1024 * 1024;
// So at most this many auxiliary points (one bit each).
inline constexpr double kMaxAuxPoints = 8.0 * kMaxAuxBytes;

struct AuxGrid {
  Vec3 origin = Vec3::Zero();
  double step = 0.0;
  std::array<long long, 3> n{0, 0, 0};
  std::vector<std::uint64_t> bits;  // 1 = alive
  long long live = 0, initial = 0;

  long long at(long long i, long long j, long long k) const { return i + n[0] * (j + n[1] * k); }
  bool alive(long long id) const { return (bits[id >> 6] >> (id & 63)) & 1U; }
  Vec3 point(long long i, long long j, long long k) const {
    return origin + step * Vec3(double(i), double(j), double(k));
  }
};

// The points of the grid make_aux_grid lays over the box [lo, hi] at `step` (as a double: it
// may exceed any integer for an absurd step).
double aux_grid_points(const Vec3& lo, const Vec3& hi, double step);

// The grid of `step` over the box of the region's boundary triangles (outer surfaces facing
// in or out, holes alike), its points alive where a ray along x crosses the triangles an odd
// number of times. The grid is offset by a generic fraction of a step so that no point lies
// on an axis-aligned face.
AuxGrid make_aux_grid(const std::vector<Vec3>& points,
                      const std::vector<std::array<Index, 3>>& triangles, double step);

// Live points within `radius` of `centre`, counted on every `stride`-th grid line.
long long count_live_in_ball(const AuxGrid& grid, const Vec3& centre, double radius, int stride);

// Whether a deleted point (or the grid's outside) lies within `radius` of `centre`.
bool deleted_in_ball(const AuxGrid& grid, const Vec3& centre, double radius);

// Whether a deleted point lies strictly inside the positive tet (a, b, c, d), more than a
// relative margin from its faces.
bool deleted_strictly_inside(const AuxGrid& grid, const std::array<Vec3, 4>& tet);

// Deletes the live points inside or on the tet; returns how many. Appends those on every
// `stride`-th grid line (the ones count_live_in_ball counts) to `on_lattice`.
long long delete_covered(AuxGrid& grid, const std::array<Vec3, 4>& tet, int stride,
                         std::vector<Vec3>& on_lattice);

}  // namespace volmesh::tet::front
