#pragma once
// The auxiliary points: n^3 points in each leaf of the auxiliary cells (aux_cells.hpp), one bit
// each (alive or deleted). Points outside the region are deleted from the start, so "deleted"
// means outside the region or inside a tet made already. A point's id is its leaf times n^3
// plus i + n (j + n k), (i, j, k) its place in the leaf.
#include <array>
#include <cstdint>
#include <vector>

#include "aux_cells.hpp"
#include "size_field.hpp"
#include "volmesh/core/types.hpp"

namespace volmesh::tet::front {

// The points' bits take at most this much memory: a sixth of the 24 GiB the project's machines
// have, so that the mesh, the fallback and the checks beside it still fit.
inline constexpr double kMaxAuxBytes = 4.0 * 1024 * 1024 * 1024;
// So at most this many auxiliary points (one bit each).
inline constexpr double kMaxAuxPoints = 8.0 * kMaxAuxBytes;

struct AuxGrid {
  AuxCells cells;
  long long per_leaf = 0;           // n^3
  std::vector<std::uint64_t> bits;  // 1 = alive
  long long live = 0, initial = 0;
  // For a uniform size (every leaf of level 0): the points along each axis of the one grid
  // they make, origin + step0 (i, j, k); 0 when graded.
  std::array<long long, 3> n{0, 0, 0};

  bool alive(long long id) const { return (bits[id >> 6] >> (id & 63)) & 1U; }
  // A uniform grid's point (i, j, k), 0 <= i < n[0] ...: its id and place.
  long long at(long long i, long long j, long long k) const;
  Vec3 point(long long i, long long j, long long k) const {
    return cells.origin + cells.step0 * Vec3(double(i), double(j), double(k));
  }
};

// A deleted point on the counting lattice (count_live_in_ball's), with its weight there.
struct LatticePoint {
  Vec3 p;
  double weight;
};

// The points of a uniform grid laid over the box [lo, hi] at `step` (as a double: it may
// exceed any integer for an absurd step): those the auxiliary cells hold at least, at step
// (the field's largest size) / n.
double aux_grid_points(const Vec3& lo, const Vec3& hi, double step);

// The points of the cells over the box of the region's boundary triangles (outer surfaces
// facing in or out, holes alike) for the field's sizes, n along a leaf's side, alive where a
// ray along x crosses the triangles an odd number of times. The cells must hold at most
// kMaxAuxPoints (aux_points_needed).
AuxGrid make_aux_grid(const std::vector<Vec3>& points,
                      const std::vector<std::array<Index, 3>>& triangles, const SizeField& field,
                      int n);

// The same for one grid of `step` (a uniform size), its points reached by AuxGrid::at.
AuxGrid make_aux_grid(const std::vector<Vec3>& points,
                      const std::vector<std::array<Index, 3>>& triangles, double step);

// The points make_aux_grid would lay over the box [lo, hi], or a number above kMaxAuxPoints
// once they exceed it.
double aux_points_needed(const Vec3& lo, const Vec3& hi, const SizeField& field, int n);

// Live points within `radius` of `centre` on the counting lattice (every `stride`-th grid
// line of each leaf's level), each weighted by its volume in units of the finest level's.
double count_live_in_ball(const AuxGrid& grid, const Vec3& centre, double radius, int stride);

// Whether a deleted point (or the grid's outside) lies within `radius` of `centre`.
bool deleted_in_ball(const AuxGrid& grid, const Vec3& centre, double radius);

// Whether a deleted point lies strictly inside the positive tet (a, b, c, d), more than a
// relative margin from its faces.
bool deleted_strictly_inside(const AuxGrid& grid, const std::array<Vec3, 4>& tet);

// Deletes the live points inside or on the tet; returns how many. Appends those on the
// counting lattice (the ones count_live_in_ball counts), with their weights, to `on_lattice`.
long long delete_covered(AuxGrid& grid, const std::array<Vec3, 4>& tet, int stride,
                         std::vector<LatticePoint>& on_lattice);

}  // namespace volmesh::tet::front
