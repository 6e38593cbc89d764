#pragma once
// Walking a segment a + t d, t in [0, 1], through a regular grid of cells (Amanatides-Woo):
// the parameter intervals in which it stays inside one cell, in order. Shared by the
// labelled-image and signed-distance-grid crossings.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "volmesh/core/types.hpp"

namespace volmesh::voxel {

struct CellGrid {
  Vec3 lo;                     // corner of cell (0, 0, 0)
  Vec3 h;                      // cell size
  std::array<Index, 3> cells;  // cells along x, y, z
  Vec3 hi() const { return lo + h.cwiseProduct(Vec3(cells[0], cells[1], cells[2])); }
};

// The part of the segment inside the closed box [lo, hi]; axis0 / axis1: the axis of the face
// through which it enters / leaves (-1 where an endpoint is inside or on the box).
struct Clip {
  double t0 = 0.0, t1 = 1.0;
  int axis0 = -1, axis1 = -1;
};
std::optional<Clip> clip_segment(const Vec3& lo, const Vec3& hi, const Vec3& a, const Vec3& d);

// [t0, t1] of positive length inside one cell; axis / plane: the grid plane crossed at t0
// (for the first piece, the box face through which the segment enters; axis -1 if a is
// inside).
struct Piece {
  double t0, t1;
  int axis;
  double plane;
};

template <class F>
void for_each_piece(const CellGrid& grid, const Vec3& a, const Vec3& d, const Clip& clip, F&& f) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  std::array<double, 3> next{kNever, kNever, kNever};  // t of the next plane along each axis
  std::array<double, 3> k{}, step{};                   // index of that plane, and +-1
  const Vec3 start = a + clip.t0 * d;
  const auto plane_t = [&](int m) { return (grid.lo[m] + k[m] * grid.h[m] - a[m]) / d[m]; };
  for (int m = 0; m < 3; ++m) {
    if (d[m] == 0.0) continue;
    const double u = (start[m] - grid.lo[m]) / grid.h[m];
    step[m] = d[m] > 0.0 ? 1.0 : -1.0;
    k[m] = d[m] > 0.0 ? std::floor(u) + 1.0 : std::ceil(u) - 1.0;
    next[m] = plane_t(m);
  }
  Piece piece{clip.t0, clip.t0, clip.axis0, 0.0};
  if (clip.axis0 >= 0)
    piece.plane = d[clip.axis0] > 0.0 ? grid.lo[clip.axis0] : grid.hi()[clip.axis0];
  // Each step passes one plane; the box has cells + 1 planes per axis (+2 for rounding).
  for (Index guard = grid.cells[0] + grid.cells[1] + grid.cells[2] + 9; guard > 0; --guard) {
    const int m = static_cast<int>(std::min_element(next.begin(), next.end()) - next.begin());
    const double t = std::min(next[m], clip.t1);
    if (t > piece.t0) {
      piece.t1 = t;
      f(piece);
      piece.t0 = t;
    }
    if (next[m] >= clip.t1) return;
    piece.axis = m;
    piece.plane = grid.lo[m] + k[m] * grid.h[m];
    k[m] += step[m];
    next[m] = plane_t(m);
  }
}

}  // namespace volmesh::voxel
