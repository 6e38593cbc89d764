#include "aux_grid.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace volmesh::tet::front {

namespace {

// The grid's offset from the box corner, in steps: generic, so that grid points and lines
// miss the faces and edges of axis-aligned and symmetric models.
const Vec3 kOffset(0.3183098861837907, 0.2718281828459045, 0.1414213562373095);
// The grid's origin for the box corner lo, and its points along an axis of extent [lo, hi]:
// a step and the offset below lo, and two steps beyond hi.
Vec3 grid_origin(const Vec3& lo, double step) { return lo - step * (Vec3::Ones() + kOffset); }
double points_along(double origin, double hi, double step) {
  return std::ceil((hi - origin) / step) + 2.0;
}

// Barycentric margin telling "strictly inside" from "on a face" for points computed in doubles.
constexpr double kMargin = 1e-9;

void set_alive(AuxGrid& g, long long id) { g.bits[id >> 6] |= std::uint64_t{1} << (id & 63); }
void set_deleted(AuxGrid& g, long long id) { g.bits[id >> 6] &= ~(std::uint64_t{1} << (id & 63)); }

double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// The index range [lo, hi] of grid coordinates within [a, b] along `axis`, clamped.
std::pair<long long, long long> range(const AuxGrid& g, int axis, double a, double b) {
  const double o = g.origin[axis];
  const long long lo = std::max<long long>(0, static_cast<long long>(std::ceil((a - o) / g.step)));
  const long long hi =
      std::min<long long>(g.n[axis] - 1, static_cast<long long>(std::floor((b - o) / g.step)));
  return {lo, hi};
}

// The barycentric coordinates of p in tet t: (λ0, λ1, λ2, λ3), summing to 1.
struct Barycentric {
  Eigen::Matrix3d inverse;
  Vec3 a;
  std::array<double, 4> operator()(const Vec3& p) const {
    const Vec3 l = inverse * (p - a);
    return {1.0 - l.sum(), l[0], l[1], l[2]};
  }
};

Barycentric barycentric(const std::array<Vec3, 4>& t) {
  Eigen::Matrix3d m;
  m.col(0) = t[1] - t[0];
  m.col(1) = t[2] - t[0];
  m.col(2) = t[3] - t[0];
  return {m.inverse(), t[0]};
}

// The grid's index ranges over the tet's box: i0, i1, j0, j1, k0, k1.
std::array<long long, 6> box_ranges(const AuxGrid& g, const std::array<Vec3, 4>& t) {
  Vec3 lo = t[0], hi = t[0];
  for (const Vec3& p : t) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const auto [i0, i1] = range(g, 0, lo.x(), hi.x());
  const auto [j0, j1] = range(g, 1, lo.y(), hi.y());
  const auto [k0, k1] = range(g, 2, lo.z(), hi.z());
  return {i0, i1, j0, j1, k0, k1};
}

// Calls f(id, point) for every grid point in the tet's box.
template <class F>
void for_each_in_box(const AuxGrid& g, const std::array<Vec3, 4>& t, F&& f) {
  const auto [i0, i1, j0, j1, k0, k1] = box_ranges(g, t);
  for (long long k = k0; k <= k1; ++k)
    for (long long j = j0; j <= j1; ++j)
      for (long long i = i0; i <= i1; ++i)
        if (f(g.at(i, j, k), g.point(i, j, k))) return;
}

// Barycentric slack of the rows' ranges below: far looser than kMargin and than the rounding
// of a barycentric coordinate, so that a range never leaves out a point the test would keep.
constexpr double kRowSlack = 1e-6;

// Calls f(id, point) for the grid points in the tet's box whose row (along x) runs inside the
// tet, each row cut to the stretch where every barycentric coordinate, linear along it, is
// above -kRowSlack (widened by a point each way): the points of the box the tet holds, and a
// few more.
template <class F>
void for_each_in_tet_rows(const AuxGrid& g, const std::array<Vec3, 4>& t, const Barycentric& bary,
                          F&& f) {
  const auto [i0, i1, j0, j1, k0, k1] = box_ranges(g, t);
  if (i0 > i1) return;
  // Each coordinate's change per step along x.
  const std::array<double, 4> at0 = bary(g.point(i0, j0, k0)), at1 = bary(g.point(i0 + 1, j0, k0));
  std::array<double, 4> slope{};
  for (int m = 0; m < 4; ++m) slope[m] = at1[m] - at0[m];
  for (long long k = k0; k <= k1; ++k)
    for (long long j = j0; j <= j1; ++j) {
      const std::array<double, 4> start = bary(g.point(i0, j, k));
      double first = static_cast<double>(i0), last = static_cast<double>(i1);
      for (int m = 0; m < 4 && first <= last; ++m) {
        // start[m] + slope[m] (i - i0) > -kRowSlack.
        const double excess = start[m] + kRowSlack;
        if (slope[m] > 0.0)
          first = std::max(first, static_cast<double>(i0) - excess / slope[m] - 1.0);
        else if (slope[m] < 0.0)
          last = std::min(last, static_cast<double>(i0) - excess / slope[m] + 1.0);
        else if (excess <= 0.0)
          last = first - 1.0;
      }
      if (first > last) continue;
      const long long from = std::max(i0, static_cast<long long>(std::floor(first)));
      const long long to = std::min(i1, static_cast<long long>(std::ceil(last)));
      for (long long i = from; i <= to; ++i)
        if (f(g.at(i, j, k), g.point(i, j, k))) return;
    }
}

}  // namespace

double aux_grid_points(const Vec3& lo, const Vec3& hi, double step) {
  const Vec3 origin = grid_origin(lo, step);
  double count = 1.0;
  for (int a = 0; a < 3; ++a) count *= points_along(origin[a], hi[a], step);
  return count;
}

AuxGrid make_aux_grid(const std::vector<Vec3>& points,
                      const std::vector<std::array<Index, 3>>& triangles, double step) {
  AuxGrid g;
  Vec3 lo = points[triangles.front()[0]], hi = lo;
  for (const auto& t : triangles)
    for (const Index v : t) {
      lo = lo.cwiseMin(points[v]);
      hi = hi.cwiseMax(points[v]);
    }
  g.step = step;
  g.origin = grid_origin(lo, step);
  for (int a = 0; a < 3; ++a)
    g.n[a] = static_cast<long long>(points_along(g.origin[a], hi[a], step));
  const long long total = g.n[0] * g.n[1] * g.n[2];
  g.bits.assign(static_cast<std::size_t>((total + 63) / 64), 0);
  // Crossings of the x-lines (j, k) with the triangles, as (line, x).
  std::vector<std::pair<long long, double>> crossings;
  for (const auto& t : triangles) {
    const Vec3 &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    const double d = cross2(b.y() - a.y(), b.z() - a.z(), c.y() - a.y(), c.z() - a.z());
    if (d == 0.0) continue;  // parallel to x: no line crosses it
    const auto [j0, j1] = range(g, 1, std::min({a.y(), b.y(), c.y()}), std::max({a.y(), b.y(), c.y()}));
    const auto [k0, k1] = range(g, 2, std::min({a.z(), b.z(), c.z()}), std::max({a.z(), b.z(), c.z()}));
    for (long long k = k0; k <= k1; ++k)
      for (long long j = j0; j <= j1; ++j) {
        const Vec3 p = g.point(0, j, k);
        const double wa = cross2(b.y() - p.y(), b.z() - p.z(), c.y() - p.y(), c.z() - p.z()) / d;
        const double wb = cross2(c.y() - p.y(), c.z() - p.z(), a.y() - p.y(), a.z() - p.z()) / d;
        const double wc = 1.0 - wa - wb;
        if (wa <= 0.0 || wb <= 0.0 || wc <= 0.0) continue;
        crossings.emplace_back(j + g.n[1] * k, wa * a.x() + wb * b.x() + wc * c.x());
      }
  }
  std::sort(crossings.begin(), crossings.end());
  for (std::size_t s = 0; s < crossings.size();) {
    std::size_t e = s;
    while (e < crossings.size() && crossings[e].first == crossings[s].first) ++e;
    const long long line = crossings[s].first;
    const long long j = line % g.n[1], k = line / g.n[1];
    // An odd count (a line through an edge, counted on neither side) leaves the line empty.
    if ((e - s) % 2 == 0)
      for (std::size_t c = s; c < e; c += 2) {
        const auto [i0, i1] = range(g, 0, crossings[c].second, crossings[c + 1].second);
        for (long long i = i0; i <= i1; ++i) {
          const Vec3 p = g.point(i, j, k);
          if (p.x() <= crossings[c].second || p.x() >= crossings[c + 1].second) continue;
          set_alive(g, g.at(i, j, k));
          ++g.live;
        }
      }
    s = e;
  }
  g.initial = g.live;
  return g;
}

long long count_live_in_ball(const AuxGrid& g, const Vec3& centre, double radius, int stride) {
  long long count = 0;
  const auto [i0, i1] = range(g, 0, centre.x() - radius, centre.x() + radius);
  const auto [j0, j1] = range(g, 1, centre.y() - radius, centre.y() + radius);
  const auto [k0, k1] = range(g, 2, centre.z() - radius, centre.z() + radius);
  // Lines on the stride lattice of the whole grid, so the count does not depend on the centre's
  // rounding.
  const auto first = [stride](long long lo) { return (lo + stride - 1) / stride * stride; };
  const double r2 = radius * radius;
  for (long long k = first(k0); k <= k1; k += stride)
    for (long long j = first(j0); j <= j1; j += stride)
      for (long long i = first(i0); i <= i1; i += stride)
        if ((g.point(i, j, k) - centre).squaredNorm() <= r2 && g.alive(g.at(i, j, k))) ++count;
  return count;
}

bool deleted_in_ball(const AuxGrid& g, const Vec3& centre, double radius) {
  for (int a = 0; a < 3; ++a)
    if (centre[a] - radius < g.origin[a] ||
        centre[a] + radius > g.origin[a] + g.step * double(g.n[a] - 1))
      return true;
  const auto [i0, i1] = range(g, 0, centre.x() - radius, centre.x() + radius);
  const auto [j0, j1] = range(g, 1, centre.y() - radius, centre.y() + radius);
  const auto [k0, k1] = range(g, 2, centre.z() - radius, centre.z() + radius);
  const double r2 = radius * radius;
  for (long long k = k0; k <= k1; ++k)
    for (long long j = j0; j <= j1; ++j)
      for (long long i = i0; i <= i1; ++i)
        if ((g.point(i, j, k) - centre).squaredNorm() <= r2 && !g.alive(g.at(i, j, k)))
          return true;
  return false;
}

bool deleted_strictly_inside(const AuxGrid& g, const std::array<Vec3, 4>& tet) {
  const Barycentric bary = barycentric(tet);
  bool found = false;
  for_each_in_tet_rows(g, tet, bary, [&](long long id, const Vec3& p) {
    if (g.alive(id)) return false;
    const auto l = bary(p);
    found = std::all_of(l.begin(), l.end(), [](double x) { return x > kMargin; });
    return found;
  });
  return found;
}

long long delete_covered(AuxGrid& g, const std::array<Vec3, 4>& tet, int stride,
                         std::vector<Vec3>& on_lattice) {
  const Barycentric bary = barycentric(tet);
  long long count = 0;
  for_each_in_box(g, tet, [&](long long id, const Vec3& p) {
    if (!g.alive(id)) return false;
    const auto l = bary(p);
    if (std::all_of(l.begin(), l.end(), [](double x) { return x >= -kMargin; })) {
      set_deleted(g, id);
      ++count;
      const long long i = id % g.n[0], j = id / g.n[0] % g.n[1], k = id / (g.n[0] * g.n[1]);
      if (i % stride == 0 && j % stride == 0 && k % stride == 0) on_lattice.push_back(p);
    }
    return false;
  });
  g.live -= count;
  return count;
}

}  // namespace volmesh::tet::front
