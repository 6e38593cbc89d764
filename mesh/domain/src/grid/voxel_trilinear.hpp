#pragma once
// The trilinear interpolant of one grid cell, at a point and along a segment, where it is a
// cubic in the segment's parameter; and that cubic's roots.
#include <array>

#include "volmesh/core/types.hpp"

namespace volmesh::voxel {

// Corner values of a cell indexed x + 2y + 4z; f: coordinates in the cell, in [0, 1].
// Interpolates along x, then y, then z.
inline double trilinear(const std::array<double, 8>& c, const Vec3& f) {
  const auto lerp = [](double a, double b, double t) { return a + t * (b - a); };
  const double y0 = lerp(lerp(c[0], c[1], f.x()), lerp(c[2], c[3], f.x()), f.y());
  const double y1 = lerp(lerp(c[4], c[5], f.x()), lerp(c[6], c[7], f.x()), f.y());
  return lerp(y0, y1, f.z());
}

// c[0] + c[1] s + c[2] s^2 + c[3] s^3
struct Cubic {
  std::array<double, 4> c{};
  double operator()(double s) const { return c[0] + s * (c[1] + s * (c[2] + s * c[3])); }
  double derivative(double s) const { return c[1] + s * (2.0 * c[2] + s * 3.0 * c[3]); }
};

// The interpolant at cell coordinates f0 + s df, as a cubic in s.
Cubic cubic_along(const std::array<double, 8>& corners, const Vec3& f0, const Vec3& df);

// The points in (0, len) where g' = 0, ascending; returns how many (at most 2).
int critical_points(const Cubic& g, double len, std::array<double, 2>& out);

// The root of g in [lo, hi], g monotone there and rising (g(lo) < 0 < g(hi)) or falling:
// a Newton iteration kept inside the shrinking bracket, to the last bit.
double bracketed_root(const Cubic& g, double lo, double hi, bool rising);

}  // namespace volmesh::voxel
