// Sheets as exact graphs over a rectangle: the checks, a bucket grid (with each bucket's
// height range) for locating the triangle above a point and the triangles near a segment,
// and the side of a point (CGAL's filtered exact predicates).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "layered_model.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh {

namespace layers {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;
using Point3 = Kernel::Point_3;

constexpr double kSnap = 1e-6;  // relative to the rectangle's sides
// The projections' areas add up to the rectangle's to this relative rounding when they tile
// it once; a sheet covering it twice is off by a whole rectangle.
constexpr double kAreaRounding = 1e-9;

Point3 point3(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

std::string coordinates(const Vec3& p) {
  std::ostringstream s;
  s.precision(9);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

std::string plane_name(int axis) {
  static const char* names[] = {"y-z", "z-x", "x-y"};
  return names[axis];
}

}  // namespace

GraphSheet::GraphSheet(const Sheet& sheet, const Box3& box, const std::string& model)
    : axis(sheet.axis), u((sheet.axis + 1) % 3), v((sheet.axis + 2) % 3), name(sheet.name) {
  const std::string who = model + ": sheet '" + name + "'";
  if (axis < 0 || axis > 2)
    throw InputError(who + ": axis " + std::to_string(axis) + " (expected 0, 1 or 2)");
  const std::string plane = plane_name(axis) + " rectangle";
  u0_ = box.lo[u], u1_ = box.hi[u], v0_ = box.lo[v], v1_ = box.hi[v];
  const TriSurface& s = sheet.surface;
  if (s.triangles.empty()) throw InputError(who + ": no triangles");
  points = s.points;
  triangles = s.triangles;

  std::vector<char> used(points.size(), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (Index c : triangles[t]) {
      if (c < 0 || c >= s.num_points())
        throw InputError(who + ": triangle " + std::to_string(t) + ": vertex index " +
                         std::to_string(c) + " out of range (" + std::to_string(s.num_points()) +
                         " vertices)");
      used[c] = 1;
    }
  // Vertices within kSnap of the border are put on it: surface files in float (STL) cannot
  // hold the box's coordinates exactly.
  const auto snap = [](double& x, double lo, double hi) {
    const double tolerance = kSnap * (hi - lo);
    if (std::abs(x - lo) <= tolerance) x = lo;
    if (std::abs(x - hi) <= tolerance) x = hi;
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!used[i]) continue;
    Vec3& p = points[i];
    if (!p.allFinite())
      throw InputError(who + ": vertex " + std::to_string(i) + ": coordinate is not finite");
    snap(p[u], u0_, u1_);
    snap(p[v], v0_, v1_);
    if (!over(p))
      throw InputError(who + ": vertex " + std::to_string(i) + " at " + coordinates(p) +
                       " lies outside the box's " + plane);
  }

  // Every triangle must project to a proper triangle, all turning the same way.
  const auto orientation = [&](const std::array<Index, 3>& t) {
    const auto q = [&](Index c) { return Point2(points[c][u], points[c][v]); };
    return CGAL::orientation(q(t[0]), q(t[1]), q(t[2]));
  };
  double area = 0.0;
  int turn = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const CGAL::Orientation o = orientation(triangles[t]);
    if (o == CGAL::COLLINEAR)
      throw InputError(who + ": triangle " + std::to_string(t) +
                       " is vertical (its projection on the " + plane_name(axis) +
                       " plane is degenerate): the sheet is not a graph over it");
    const int o_sign = o == CGAL::POSITIVE ? 1 : -1;
    if (turn == 0) turn = o_sign;
    if (o_sign != turn)
      throw InputError(who + ": triangle " + std::to_string(t) + " folds over triangle 0 " +
                       "(their projections turn opposite ways): the sheet is not a graph over "
                       "the " +
                       plane);
    const Vec3 e1 = points[triangles[t][1]] - points[triangles[t][0]];
    const Vec3 e2 = points[triangles[t][2]] - points[triangles[t][0]];
    area += std::abs(e1[u] * e2[v] - e1[v] * e2[u]) / 2.0;
  }
  if (turn < 0)
    for (auto& t : triangles) std::swap(t[1], t[2]);

  // Sides shared by two triangles run opposite ways; the others lie on the rectangle's border.
  struct Side {
    std::uint64_t key;
    Index triangle;
    int k;
  };
  // Grouped by their lower vertex (a counting sort), then sorted within each group.
  std::vector<std::size_t> first(points.size() + 1, 0);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) ++first[std::min(t[k], t[(k + 1) % 3]) + 1];
  for (std::size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];
  std::vector<Side> sides(3 * triangles.size());
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  for (Index t = 0; t < static_cast<Index>(triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      sides[fill[std::min(a, b)]++] = {std::min(a, b) << 32 | std::max(a, b), t, k};
    }
  for (std::size_t i = 0; i + 1 < first.size(); ++i)
    std::sort(sides.begin() + first[i], sides.begin() + first[i + 1],
              [](const Side& x, const Side& y) {
                return x.key != y.key ? x.key < y.key : x.triangle < y.triangle;
              });
  across.assign(triangles.size(), {kNoIndex, kNoIndex, kNoIndex});
  const auto on_border = [&](const Vec3& a, const Vec3& b) {
    return (a[u] == u0_ && b[u] == u0_) || (a[u] == u1_ && b[u] == u1_) ||
           (a[v] == v0_ && b[v] == v0_) || (a[v] == v1_ && b[v] == v1_);
  };
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].key == sides[i].key) ++j;
    const Side& x = sides[i];
    const Index a = static_cast<Index>(x.key >> 32), b = static_cast<Index>(x.key & 0xffffffffu);
    const auto edge = [&] { return "edge " + std::to_string(a) + "-" + std::to_string(b); };
    if (j - i > 2)
      throw InputError(who + ": " + edge() + " is shared by " + std::to_string(j - i) +
                       " triangles (non-manifold)");
    if (j - i == 1 && !on_border(points[a], points[b]))
      throw InputError(who + ": " + edge() + " at " + coordinates(0.5 * (points[a] + points[b])) +
                       " is a border edge inside the box's " + plane +
                       ": the sheet has a hole or does not span the box");
    if (j - i == 2) {
      const Side& y = sides[i + 1];
      if (triangles[x.triangle][x.k] == triangles[y.triangle][y.k])
        throw InputError(who + ": triangles " + std::to_string(x.triangle) + " and " +
                         std::to_string(y.triangle) + " overlap across " + edge() +
                         ": the sheet is not a graph over the " + plane);
      across[x.triangle][x.k] = y.triangle;
      across[y.triangle][y.k] = x.triangle;
    }
    i = j;
  }
  // Border edges on the border and no fold: the projections cover the rectangle a whole
  // number of times, which the area tells.
  const double rectangle = (u1_ - u0_) * (v1_ - v0_);
  if (std::abs(area - rectangle) > kAreaRounding * rectangle)
    throw InputError(who + ": its triangles cover the box's " + plane + " " +
                     std::to_string(std::lround(area / rectangle)) +
                     " times over: the sheet is not a graph over it");
  build_buckets();
}

bool GraphSheet::over(const Vec3& p) const {
  return p[u] >= u0_ && p[u] <= u1_ && p[v] >= v0_ && p[v] <= v1_;
}

// Monotone in pu and pv (rounding included), so a triangle's box and a point inside it
// fall into overlapping bucket ranges.
std::array<Index, 2> GraphSheet::bucket(double pu, double pv) const {
  const auto clamp = [](double x, Index n) {
    return static_cast<Index>(std::clamp(std::floor(x), 0.0, static_cast<double>(n - 1)));
  };
  return {clamp((pu - u0_) * scale_u_, nu_), clamp((pv - v0_) * scale_v_, nv_)};
}

void GraphSheet::build_buckets() {
  // About two triangles per bucket, buckets about square.
  const double wu = u1_ - u0_, wv = v1_ - v0_;
  const double cells = std::max(1.0, static_cast<double>(triangles.size()) / 2.0);
  const double size = std::sqrt(wu * wv / cells);
  nu_ = static_cast<Index>(std::clamp(std::ceil(wu / size), 1.0, 4096.0));
  nv_ = static_cast<Index>(std::clamp(std::ceil(wv / size), 1.0, 4096.0));
  scale_u_ = nu_ / wu;
  scale_v_ = nv_ / wv;
  std::vector<std::array<Index, 4>> range(triangles.size());
  first_.assign(static_cast<std::size_t>(nu_) * nv_ + 1, 0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    Vec3 lo = points[triangles[t][0]], hi = lo;
    for (Index c : triangles[t]) {
      lo = lo.cwiseMin(points[c]);
      hi = hi.cwiseMax(points[c]);
    }
    const auto a = bucket(lo[u], lo[v]), b = bucket(hi[u], hi[v]);
    range[t] = {a[0], b[0], a[1], b[1]};
    for (Index j = a[1]; j <= b[1]; ++j)
      for (Index i = a[0]; i <= b[0]; ++i) ++first_[i + nu_ * j + 1];
  }
  for (std::size_t k = 1; k < first_.size(); ++k) first_[k] += first_[k - 1];
  members_.resize(first_.back());
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  w_range_.assign(first_.size() - 1, {kInfinity, -kInfinity});
  w0_ = kInfinity;
  w1_ = -kInfinity;
  std::vector<Index> fill(first_.begin(), first_.end() - 1);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& c = triangles[t];
    const double w_lo = std::min({points[c[0]][axis], points[c[1]][axis], points[c[2]][axis]});
    const double w_hi = std::max({points[c[0]][axis], points[c[1]][axis], points[c[2]][axis]});
    w0_ = std::min(w0_, w_lo);
    w1_ = std::max(w1_, w_hi);
    for (Index j = range[t][2]; j <= range[t][3]; ++j)
      for (Index i = range[t][0]; i <= range[t][1]; ++i) {
        members_[fill[i + nu_ * j]++] = static_cast<Index>(t);
        auto& [lo, hi] = w_range_[i + nu_ * j];
        lo = std::min(lo, w_lo);
        hi = std::max(hi, w_hi);
      }
  }
}

// A triangle meeting the box has a point in it whose bucket, by the monotony of bucket(),
// lies in the box's bucket range and in the triangle's: the triangle is among its members.
bool GraphSheet::triangles_near(const Vec3& lo, const Vec3& hi, std::size_t max_buckets,
                                std::vector<Index>& out) const {
  out.clear();
  if (hi[axis] < w0_ || lo[axis] > w1_) return true;
  const auto a = bucket(lo[u], lo[v]), b = bucket(hi[u], hi[v]);
  if (static_cast<std::size_t>(b[0] - a[0] + 1) * static_cast<std::size_t>(b[1] - a[1] + 1) > max_buckets)
    return false;
  if (hi[u] < u0_ || lo[u] > u1_ || hi[v] < v0_ || lo[v] > v1_) return true;
  for (Index j = a[1]; j <= b[1]; ++j)
    for (Index i = a[0]; i <= b[0]; ++i) {
      const Index k = i + nu_ * j;
      if (w_range_[k][0] > hi[axis] || w_range_[k][1] < lo[axis]) continue;
      for (Index m = first_[k]; m < first_[k + 1]; ++m) {
        const auto& t = triangles[members_[m]];
        const Vec3 &p = points[t[0]], &q = points[t[1]], &r = points[t[2]];
        if ((p.cwiseMax(q).cwiseMax(r).array() >= lo.array()).all() &&
            (p.cwiseMin(q).cwiseMin(r).array() <= hi.array()).all())
          out.push_back(members_[m]);
      }
    }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return true;
}

Index GraphSheet::locate(const Vec3& p) const {
  if (!over(p)) return kNoIndex;
  const auto [i, j] = bucket(p[u], p[v]);
  return locate_in(p, i + nu_ * j);
}

Index GraphSheet::locate_in(const Vec3& p, Index cell) const {
  const Point2 q(p[u], p[v]);
  for (Index k = first_[cell]; k < first_[cell + 1]; ++k) {
    const auto& t = triangles[members_[k]];
    const Vec3 &x = points[t[0]], &y = points[t[1]], &z = points[t[2]];
    if (p[u] < std::min({x[u], y[u], z[u]}) || p[u] > std::max({x[u], y[u], z[u]}) ||
        p[v] < std::min({x[v], y[v], z[v]}) || p[v] > std::max({x[v], y[v], z[v]}))
      continue;  // outside its box: no predicate needed
    const auto corner = [&](int c) { return Point2(points[t[c]][u], points[t[c]][v]); };
    const Point2 a = corner(0), b = corner(1), c = corner(2);
    if (CGAL::orientation(a, b, q) != CGAL::NEGATIVE &&
        CGAL::orientation(b, c, q) != CGAL::NEGATIVE &&
        CGAL::orientation(c, a, q) != CGAL::NEGATIVE)
      return members_[k];
  }
  return kNoIndex;  // unreachable for a sheet tiling the rectangle
}

int GraphSheet::side(const Vec3& p) const {
  if (!over(p)) return kUnknown;
  // The triangle under p is one of its bucket's, which lie between the bucket's heights.
  const auto [i, j] = bucket(p[u], p[v]);
  const auto& [lo, hi] = w_range_[i + nu_ * j];
  if (lo <= hi && p[axis] > hi) return 1;
  if (lo <= hi && p[axis] < lo) return -1;
  const Index t = locate_in(p, i + nu_ * j);
  if (t == kNoIndex) return kUnknown;
  const auto& c = triangles[t];
  const CGAL::Orientation o = CGAL::orientation(point3(points[c[0]]), point3(points[c[1]]),
                                                point3(points[c[2]]), point3(p));
  return o == CGAL::POSITIVE ? 1 : o == CGAL::NEGATIVE ? -1 : 0;
}

void add_sheet(surface::SurfaceGeometry& g, const GraphSheet& sheet) {
  const Index offset = static_cast<Index>(g.points.size());
  const Index first = g.num_triangles();
  if (static_cast<std::int64_t>(g.points.size()) + sheet.points.size() > kMaxIndex ||
      static_cast<std::int64_t>(g.triangles.size()) + sheet.triangles.size() > kMaxIndex)
    throw InputError("sheet '" + sheet.name + "': too many points or triangles (32-bit indices)");
  g.points.insert(g.points.end(), sheet.points.begin(), sheet.points.end());
  g.vertex_normals.resize(g.points.size(), Vec3::Zero());
  for (const auto& c : sheet.triangles) {
    g.triangles.push_back({c[0] + offset, c[1] + offset, c[2] + offset});
    g.triangle_surface.push_back(g.num_surfaces());
    const Vec3& a = sheet.points[c[0]];
    g.face_normals.push_back((sheet.points[c[1]] - a).cross(sheet.points[c[2]] - a).normalized());
  }
  for (std::size_t t = 0; t < sheet.triangles.size(); ++t) {
    const Vec3& n = g.face_normals[first + t];
    const auto& c = sheet.triangles[t];
    std::array<Vec3, 3> edges;
    for (int k = 0; k < 3; ++k) {
      const Index other = sheet.across[t][k];
      edges[k] = other == kNoIndex ? n : (n + g.face_normals[first + other]).normalized();
      const Vec3 e1 = sheet.points[c[(k + 1) % 3]] - sheet.points[c[k]];
      const Vec3 e2 = sheet.points[c[(k + 2) % 3]] - sheet.points[c[k]];
      g.vertex_normals[c[k] + offset] += std::atan2(e1.cross(e2).norm(), e1.dot(e2)) * n;
    }
    g.edge_normals.push_back(edges);
  }
  for (std::size_t p = offset; p < g.points.size(); ++p)
    if (g.vertex_normals[p] != Vec3::Zero()) g.vertex_normals[p].normalize();
  g.first_triangle.push_back(g.num_triangles());
}

}  // namespace layers

Sheet plane_sheet(const Box3& box, int axis, const Vec3& point, const Vec3& normal,
                  std::string name) {
  if (axis < 0 || axis > 2 || !(std::abs(normal[axis]) > 0.0))
    throw std::invalid_argument("plane_sheet: the plane is not a graph across the axis");
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  Sheet s{{}, axis, std::move(name)};
  for (int k = 0; k < 4; ++k) {
    Vec3 p;
    p[u] = k & 1 ? box.hi[u] : box.lo[u];
    p[v] = k & 2 ? box.hi[v] : box.lo[v];
    p[axis] = point[axis] -
              (normal[u] * (p[u] - point[u]) + normal[v] * (p[v] - point[v])) / normal[axis];
    s.surface.points.push_back(p);
  }
  s.surface.triangles = {{0, 1, 3}, {0, 3, 2}};
  return s;
}

Sheet graph_sheet(const Box3& box, int axis, Index nu, Index nv,
                  const std::function<double(double, double)>& f, std::string name) {
  if (axis < 0 || axis > 2 || nu < 2 || nv < 2 ||
      static_cast<std::int64_t>(nu) * nv > kMaxIndex / 2)
    throw std::invalid_argument("graph_sheet: needs an axis 0..2 and 2 to 2^30 grid vertices");
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  Sheet s{{}, axis, std::move(name)};
  // Grid lines at exact fractions, the last ones exactly on the box.
  const auto at = [](double lo, double hi, Index i, Index n) {
    return i == n - 1 ? hi : lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n - 1);
  };
  for (Index j = 0; j < nv; ++j)
    for (Index i = 0; i < nu; ++i) {
      Vec3 p;
      p[u] = at(box.lo[u], box.hi[u], i, nu);
      p[v] = at(box.lo[v], box.hi[v], j, nv);
      p[axis] = f(p[u], p[v]);
      s.surface.points.push_back(p);
    }
  for (Index j = 0; j + 1 < nv; ++j)
    for (Index i = 0; i + 1 < nu; ++i) {
      const Index a = i + nu * j, b = a + 1, c = a + nu, d = c + 1;
      s.surface.triangles.push_back({a, b, d});
      s.surface.triangles.push_back({a, d, c});
    }
  return s;
}

}  // namespace volmesh
