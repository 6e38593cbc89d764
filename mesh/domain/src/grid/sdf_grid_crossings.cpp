// Signed-distance grid crossings: where the sign of the trilinear field changes along a
// segment, root by root in every cell the segment passes (the walk in voxel_dda.hpp).
//
// The segment is cut into samples: each cell's entry and exit and the cubic's critical
// points in between, so that the field is monotone from one sample to the next. A sample's
// region is 1 where f >= 0; between two samples of different region there is one root, at a
// sample itself if its value is exactly 0. The value at a cell's exit is carried over as the
// next cell's entry value, so that the two cells cannot disagree about a root on their face.
#include <cmath>

#include "common/voxel_dda.hpp"
#include "volmesh/domain/grid.hpp"
#include "voxel_trilinear.hpp"

namespace volmesh {

std::vector<Crossing> SdfGridDomain::crossings(const Vec3& a, const Vec3& b) const {
  std::vector<Crossing> out;
  const Vec3 d = b - a;
  const auto& n = grid_.dims;
  const voxel::CellGrid cells{grid_.origin, grid_.spacing, {n[0] - 1, n[1] - 1, n[2] - 1}};
  const auto clip = voxel::clip_segment(grid_.origin, hi_, a, d);
  if (!clip) return out;

  Index current = 0;
  // Into region `after` at t; through a box face (axis, plane), or else where f = 0.
  const auto cross = [&](double t, Index after, int axis = -1, double plane = 0.0) {
    Crossing c;
    c.t = t;
    c.point = a + t * d;
    c.before = current;
    c.after = after;
    if (axis >= 0) {
      c.point[axis] = plane;
      c.normal = Vec3::Unit(axis) * (d[axis] > 0.0 ? 1.0 : -1.0);  // into the box or out of it
    } else {
      const Vec3 g = gradient(c.point);  // f grows into the solid
      c.normal = g.norm() > 0.0 ? Vec3((after == 1 ? g : -g).normalized()) : d.normalized();
    }
    if (!out.empty() && out.back().t == t && out.back().before == after) {
      // Into the zero set and straight back out: one tangential touch, before == after, its
      // normal out of the touching point's region (as AnalyticDomain reports touches).
      out.back().after = after;
      out.back().normal = c.normal;
    } else {
      out.push_back(c);
    }
    current = after;
  };

  double value = this->value(a + clip->t0 * d);  // at the last sample
  if (clip->t0 > 0.0) {
    if (value >= 0.0)
      cross(clip->t0, 1, clip->axis0,
            d[clip->axis0] > 0.0 ? grid_.origin[clip->axis0] : hi_[clip->axis0]);
  } else {
    current = value >= 0.0 ? 1 : 0;
  }

  voxel::for_each_piece(cells, a, d, *clip, [&](const voxel::Piece& piece) {
    Vec3 f;
    const std::int64_t base = locate(a + 0.5 * (piece.t0 + piece.t1) * d, f);
    const Vec3 corner =
        grid_.point(static_cast<Index>(base % n[0]), static_cast<Index>(base / n[0] % n[1]),
                    static_cast<Index>(base / n[0] / n[1]));
    // s = t - piece.t0; cell coordinates f0 + s df.
    const voxel::Cubic g =
        voxel::cubic_along(corners(base), (a + piece.t0 * d - corner).cwiseProduct(inv_spacing_),
                           d.cwiseProduct(inv_spacing_));
    const double len = piece.t1 - piece.t0;
    std::array<double, 2> critical;
    const int inner = voxel::critical_points(g, len, critical);
    const std::array<double, 4> s{0.0, inner > 0 ? critical[0] : len, inner > 1 ? critical[1] : len,
                                  len};
    const int count = inner + 2;
    for (int i = 1; i < count; ++i) {
      const double lo = value, hi = g(s[i]);
      if ((lo >= 0.0) != (hi >= 0.0)) {
        if (lo == 0.0)
          cross(piece.t0 + s[i - 1], 0);  // leaves the zero set it was on
        else if (hi != 0.0)
          cross(piece.t0 + voxel::bracketed_root(g, s[i - 1], s[i], hi > 0.0), hi > 0.0 ? 1 : 0);
      }
      if (const Index here = hi >= 0.0 ? 1 : 0; here != current)
        cross(piece.t0 + s[i], here);  // an exact zero
      value = hi;
    }
  });

  if (clip->t1 < 1.0 && current == 1) {
    const int axis = clip->axis1;
    cross(clip->t1, 0, axis, d[axis] > 0.0 ? hi_[axis] : grid_.origin[axis]);
  }
  return out;
}

}  // namespace volmesh
