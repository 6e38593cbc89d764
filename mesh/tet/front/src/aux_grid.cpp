#include "aux_grid.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace volmesh::tet::front {

namespace {

// Barycentric margin telling "strictly inside" from "on a face" for points computed in doubles.
constexpr double kMargin = 1e-9;
// The leaves' points along a side in a grid of one step.
constexpr int kUniformLeafPoints = 16;

void set_alive(AuxGrid& g, long long id) { g.bits[id >> 6] |= std::uint64_t{1} << (id & 63); }
void set_deleted(AuxGrid& g, long long id) { g.bits[id >> 6] &= ~(std::uint64_t{1} << (id & 63)); }

double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// A grid line or column of one level: its two indices across the axis it runs along.
std::uint64_t line_key(long long a, long long b) {
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

// One leaf's points: global indices at its level (origin + step (i, j, k)) from `base` to
// base + n - 1 along each axis.
struct LeafView {
  const AuxCells& c;
  int level;
  double step;
  std::array<long long, 3> base;
  long long first_id;

  LeafView(const AuxGrid& g, int leaf)
      : c(g.cells), level(g.cells.leaves[leaf].level), step(g.cells.step(level)),
        first_id(leaf * g.per_leaf) {
    for (int a = 0; a < 3; ++a) base[a] = c.leaves[leaf].block[a] * c.n;
  }
  Vec3 point(long long i, long long j, long long k) const {
    return c.origin + step * Vec3(double(i), double(j), double(k));
  }
  long long id(long long i, long long j, long long k) const {
    return first_id + (i - base[0]) + c.n * ((j - base[1]) + c.n * (k - base[2]));
  }
  // The index range [lo, hi] of the leaf's points within [a, b] along `axis`.
  std::pair<long long, long long> range(int axis, double a, double b) const {
    const double o = c.origin[axis];
    const long long lo = std::max<long long>(base[axis], static_cast<long long>(std::ceil((a - o) / step)));
    const long long hi = std::min<long long>(base[axis] + c.n - 1,
                                             static_cast<long long>(std::floor((b - o) / step)));
    return {lo, hi};
  }
  // The ranges over the box [lo, hi]: i0, i1, j0, j1, k0, k1.
  std::array<long long, 6> ranges(const Vec3& lo, const Vec3& hi) const {
    const auto [i0, i1] = range(0, lo.x(), hi.x());
    const auto [j0, j1] = range(1, lo.y(), hi.y());
    const auto [k0, k1] = range(2, lo.z(), hi.z());
    return {i0, i1, j0, j1, k0, k1};
  }
  // A point's weight on the counting lattice: its volume in units of the finest level's.
  double weight() const { return std::ldexp(1.0, 3 * (c.finest - level)); }
};

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

std::pair<Vec3, Vec3> box_of(const std::array<Vec3, 4>& t) {
  Vec3 lo = t[0], hi = t[0];
  for (const Vec3& p : t) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo, hi};
}

// Barycentric slack of the rows' ranges below: far looser than kMargin and than the rounding
// of a barycentric coordinate, so that a range never leaves out a point the test would keep.
constexpr double kRowSlack = 1e-6;

// Calls f(id, point) for the leaf's points in the tet's box whose row (along x) runs inside
// the tet, each row cut to the stretch where every barycentric coordinate, linear along it, is
// above -kRowSlack (widened by a point each way): the points of the box the tet holds, and a
// few more. Stops when f returns true; returns whether it did.
template <class F>
bool for_each_in_tet_rows(const LeafView& v, const std::array<long long, 6>& r,
                          const Barycentric& bary, F&& f) {
  const auto [i0, i1, j0, j1, k0, k1] = r;
  if (i0 > i1) return false;
  // Each coordinate's change per step along x.
  const std::array<double, 4> at0 = bary(v.point(i0, j0, k0)), at1 = bary(v.point(i0 + 1, j0, k0));
  std::array<double, 4> slope{};
  for (int m = 0; m < 4; ++m) slope[m] = at1[m] - at0[m];
  for (long long k = k0; k <= k1; ++k)
    for (long long j = j0; j <= j1; ++j) {
      const std::array<double, 4> start = bary(v.point(i0, j, k));
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
        if (f(v.id(i, j, k), v.point(i, j, k))) return true;
    }
  return false;
}

// The first index at or above lo on the lattice of every stride-th line.
long long on_stride(long long lo, int stride) { return (lo + stride - 1) / stride * stride; }

}  // namespace

double aux_grid_points(const Vec3& lo, const Vec3& hi, double step) {
  const Vec3 origin = aux_origin(lo, step);
  double count = 1.0;
  for (int a = 0; a < 3; ++a) count *= aux_lines(origin[a], hi[a], step);
  return count;
}

double aux_points_needed(const Vec3& lo, const Vec3& hi, const SizeField& field, int n) {
  return aux_cell_points(make_aux_cells(lo, hi, field, n, kMaxAuxPoints));
}

AuxGrid make_aux_grid(const std::vector<Vec3>& points,
                      const std::vector<std::array<Index, 3>>& triangles, const SizeField& field,
                      int n) {
  AuxGrid g;
  Vec3 lo = points[triangles.front()[0]], hi = lo;
  for (const auto& t : triangles)
    for (const Index v : t) {
      lo = lo.cwiseMin(points[v]);
      hi = hi.cwiseMax(points[v]);
    }
  g.cells = make_aux_cells(lo, hi, field, n, kMaxAuxPoints);
  const AuxCells& c = g.cells;
  g.per_leaf = static_cast<long long>(n) * n * n;
  const long long total = static_cast<long long>(c.leaves.size()) * g.per_leaf;
  g.bits.assign(static_cast<std::size_t>((total + 63) / 64), 0);
  // By level: the columns of leaves along x (block j, k) and the crossings of their x-lines
  // (j, k) with the triangles.
  const int levels = c.finest + 1;
  std::vector<std::unordered_set<std::uint64_t>> columns(levels);
  for (const AuxLeaf& l : c.leaves) columns[l.level].insert(line_key(l.block[1], l.block[2]));
  std::vector<std::unordered_map<std::uint64_t, std::vector<double>>> crossings(levels);
  for (const auto& t : triangles) {
    const Vec3 &a = points[t[0]], &b = points[t[1]], &p2 = points[t[2]];
    const double d = cross2(b.y() - a.y(), b.z() - a.z(), p2.y() - a.y(), p2.z() - a.z());
    if (d == 0.0) continue;  // parallel to x: no line crosses it
    const double y0 = std::min({a.y(), b.y(), p2.y()}), y1 = std::max({a.y(), b.y(), p2.y()});
    const double z0 = std::min({a.z(), b.z(), p2.z()}), z1 = std::max({a.z(), b.z(), p2.z()});
    for (int level = 0; level < levels; ++level) {
      if (columns[level].empty()) continue;
      const double step = c.step(level);
      const long long lines_y = c.blocks[1] * n << level, lines_z = c.blocks[2] * n << level;
      const auto index = [&](int axis, double x, double (*round)(double), long long count) {
        return std::clamp<long long>(static_cast<long long>(round((x - c.origin[axis]) / step)),
                                     0, count - 1);
      };
      const long long j0 = index(1, y0, std::ceil, lines_y), j1 = index(1, y1, std::floor, lines_y);
      const long long k0 = index(2, z0, std::ceil, lines_z), k1 = index(2, z1, std::floor, lines_z);
      for (long long k = k0; k <= k1; ++k)
        for (long long j = j0; j <= j1; ++j) {
          if (!columns[level].count(line_key(j / n, k / n))) continue;
          const Vec3 p = c.origin + step * Vec3(0.0, double(j), double(k));
          const double wa = cross2(b.y() - p.y(), b.z() - p.z(), p2.y() - p.y(), p2.z() - p.z()) / d;
          const double wb = cross2(p2.y() - p.y(), p2.z() - p.z(), a.y() - p.y(), a.z() - p.z()) / d;
          const double wc = 1.0 - wa - wb;
          if (wa <= 0.0 || wb <= 0.0 || wc <= 0.0) continue;
          crossings[level][line_key(j, k)].push_back(wa * a.x() + wb * b.x() + wc * p2.x());
        }
    }
  }
  for (auto& level : crossings)
    for (auto& [line, xs] : level) std::sort(xs.begin(), xs.end());
  // A point is alive between the crossings 2m and 2m + 1 of its line, strictly. An odd count
  // (a line through an edge, counted on neither side) leaves the line empty.
  for (int leaf = 0; leaf < static_cast<int>(c.leaves.size()); ++leaf) {
    const LeafView v(g, leaf);
    for (long long k = v.base[2]; k < v.base[2] + n; ++k)
      for (long long j = v.base[1]; j < v.base[1] + n; ++j) {
        const auto& level = crossings[v.level];
        const auto it = level.find(line_key(j, k));
        if (it == level.end() || it->second.size() % 2 != 0) continue;
        const std::vector<double>& xs = it->second;
        for (long long i = v.base[0]; i < v.base[0] + n; ++i) {
          const double x = v.point(i, j, k).x();
          const std::size_t below = std::lower_bound(xs.begin(), xs.end(), x) - xs.begin();
          if (below % 2 == 1 && xs[below] > x) {
            set_alive(g, v.id(i, j, k));
            ++g.live;
          }
        }
      }
  }
  g.initial = g.live;
  if (c.finest == 0)
    for (int a = 0; a < 3; ++a) g.n[a] = c.blocks[a] * n;
  return g;
}

AuxGrid make_aux_grid(const std::vector<Vec3>& points,
                      const std::vector<std::array<Index, 3>>& triangles, double step) {
  // A field of no boundary points is the constant cap: leaves of kUniformLeafPoints per side.
  const SizeField uniform({}, {}, step * kUniformLeafPoints, 0.0);
  return make_aux_grid(points, triangles, uniform, kUniformLeafPoints);
}

long long AuxGrid::at(long long i, long long j, long long k) const {
  const int n = cells.n;
  const long long block = i / n + cells.blocks[0] * (j / n + cells.blocks[1] * (k / n));
  return cells.nodes[block].leaf * per_leaf + i % n + n * (j % n + n * (k % n));
}

double count_live_in_ball(const AuxGrid& g, const Vec3& centre, double radius, int stride) {
  double count = 0.0;
  const Vec3 reach = Vec3::Constant(radius);
  const double r2 = radius * radius;
  for_each_leaf(g.cells, centre - reach, centre + reach, [&](int leaf) {
    const LeafView v(g, leaf);
    const auto [i0, i1, j0, j1, k0, k1] = v.ranges(centre - reach, centre + reach);
    const double w = v.weight();
    // Lines on the stride lattice of the whole level, so the count does not depend on the
    // centre's rounding.
    for (long long k = on_stride(k0, stride); k <= k1; k += stride)
      for (long long j = on_stride(j0, stride); j <= j1; j += stride)
        for (long long i = on_stride(i0, stride); i <= i1; i += stride)
          if ((v.point(i, j, k) - centre).squaredNorm() <= r2 && g.alive(v.id(i, j, k))) count += w;
  });
  return count;
}

bool deleted_in_ball(const AuxGrid& g, const Vec3& centre, double radius) {
  const AuxCells& c = g.cells;
  for (int a = 0; a < 3; ++a)
    if (centre[a] - radius < c.origin[a] || centre[a] + radius > c.last[a]) return true;
  const Vec3 reach = Vec3::Constant(radius);
  const double r2 = radius * radius;
  bool found = false;
  for_each_leaf(c, centre - reach, centre + reach, [&](int leaf) {
    if (found) return;
    const LeafView v(g, leaf);
    const auto [i0, i1, j0, j1, k0, k1] = v.ranges(centre - reach, centre + reach);
    for (long long k = k0; k <= k1 && !found; ++k)
      for (long long j = j0; j <= j1 && !found; ++j)
        for (long long i = i0; i <= i1 && !found; ++i)
          found = (v.point(i, j, k) - centre).squaredNorm() <= r2 && !g.alive(v.id(i, j, k));
  });
  return found;
}

bool deleted_strictly_inside(const AuxGrid& g, const std::array<Vec3, 4>& tet) {
  const Barycentric bary = barycentric(tet);
  const auto [lo, hi] = box_of(tet);
  bool found = false;
  for_each_leaf(g.cells, lo, hi, [&](int leaf) {
    if (found) return;
    const LeafView v(g, leaf);
    found = for_each_in_tet_rows(v, v.ranges(lo, hi), bary, [&](long long id, const Vec3& p) {
      if (g.alive(id)) return false;
      const auto l = bary(p);
      return std::all_of(l.begin(), l.end(), [](double x) { return x > kMargin; });
    });
  });
  return found;
}

long long delete_covered(AuxGrid& g, const std::array<Vec3, 4>& tet, int stride,
                         std::vector<LatticePoint>& on_lattice) {
  const Barycentric bary = barycentric(tet);
  const auto [lo, hi] = box_of(tet);
  long long count = 0;
  for_each_leaf(g.cells, lo, hi, [&](int leaf) {
    const LeafView v(g, leaf);
    const auto [i0, i1, j0, j1, k0, k1] = v.ranges(lo, hi);
    for (long long k = k0; k <= k1; ++k)
      for (long long j = j0; j <= j1; ++j)
        for (long long i = i0; i <= i1; ++i) {
          const long long id = v.id(i, j, k);
          if (!g.alive(id)) continue;
          const Vec3 p = v.point(i, j, k);
          const auto l = bary(p);
          if (!std::all_of(l.begin(), l.end(), [](double x) { return x >= -kMargin; })) continue;
          set_deleted(g, id);
          ++count;
          if (i % stride == 0 && j % stride == 0 && k % stride == 0)
            on_lattice.push_back({p, v.weight()});
        }
  });
  g.live -= count;
  return count;
}

}  // namespace volmesh::tet::front
