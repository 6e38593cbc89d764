// A triangulated reference surface: its AABB tree, and the bounded-error one-sided distance
// from another triangulation to it (Tang et al.'s scheme with a coplanar cover bound).
#include "volmesh/quality/surface_distance.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <stdexcept>
#include <vector>

namespace volmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Triangle = Kernel::Triangle_3;
using Triangles = std::vector<Triangle>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The coplanar cover bound (Target::covered_plane_bound): a piece is bounded by its distance
// to a plane only when it lies within 60° of the plane (the cosine of their normals at least
// kCoverMinCosine), where its projection keeps at least half its area; the plane's triangles
// cover the projection when their clipped areas add up to it within kCoverAreaTolerance (the
// rounding of the clipping). Target triangles within kCoplanarFraction of the error bound of
// one plane count as coplanar: a piece over them is then settled within half the bound of
// its corners, also where two surfaces lie on each other only up to rounding.
constexpr double kCoverMinCosine = 0.5;
constexpr double kCoverAreaTolerance = 1e-11;
constexpr double kCoplanarFraction = 0.25;

struct Closest {
  double distance = 0.0;
  std::size_t triangle = 0;
};

using Point2 = std::array<double, 2>;
using Polygon2 = std::vector<Point2>;

double cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double area2(const Polygon2& p) {
  double a = 0.0;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) a += cross2(p[0], p[i], p[i + 1]);
  return 0.5 * a;
}

// The part of a convex polygon inside a counter-clockwise triangle (Sutherland–Hodgman).
Polygon2 clip(Polygon2 poly, const std::array<Point2, 3>& tri) {
  for (int e = 0; e < 3 && !poly.empty(); ++e) {
    const Point2& a = tri[e];
    const Point2& b = tri[(e + 1) % 3];
    Polygon2 out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Point2& p = poly[i];
      const Point2& q = poly[(i + 1) % poly.size()];
      const double sp = cross2(a, b, p), sq = cross2(a, b, q);
      if (sp >= 0.0) out.push_back(p);
      if ((sp >= 0.0) != (sq >= 0.0)) {
        const double t = sp / (sp - sq);
        out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
      }
    }
    poly = std::move(out);
  }
  return poly;
}

// The surface distances are measured to: its triangles in an AABB tree, for closest points
// and for the triangles near a piece.
class Target {
 public:
  // Built at once, so that threads may query it together.
  explicit Target(const TriSurface& s) {
    triangles_.reserve(s.triangles.size());
    for (const auto& t : s.triangles) triangles_.emplace_back(point(s.points[t[0]]), point(s.points[t[1]]), point(s.points[t[2]]));
    tree_.insert(triangles_.cbegin(), triangles_.cend());
    tree_.build();
    tree_.accelerate_distance_queries();
  }
  Target(const Target&) = delete;
  Target& operator=(const Target&) = delete;

  static Point point(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

  Closest closest(const Point& p) const {
    const auto [q, it] = tree_.closest_point_and_primitive(p);
    return {std::sqrt(CGAL::squared_distance(p, q)), static_cast<std::size_t>(it - triangles_.cbegin())};
  }

  double distance(std::size_t triangle, const Point& p) const {
    return std::sqrt(CGAL::squared_distance(p, triangles_[triangle]));
  }

  // The plane of a triangle, with an orthonormal frame in it; nullopt for a degenerate one.
  struct Plane {
    Point origin;
    Vector normal, u, w;
    double height(const Point& p) const { return std::abs((p - origin) * normal); }
    Point2 in_plane(const Point& p) const { return {(p - origin) * u, (p - origin) * w}; }
  };
  std::optional<Plane> plane(std::size_t triangle) const {
    const Triangle& t = triangles_[triangle];
    if (t.is_degenerate()) return std::nullopt;
    Vector n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    n = n / std::sqrt(n.squared_length());
    Vector u = t[1] - t[0];
    u = u / std::sqrt(u.squared_length());
    return Plane{t[0], n, u, CGAL::cross_product(n, u)};
  }

  // Whether every corner of these triangles lies within `tolerance` of the plane.
  bool within(const Plane& plane, const std::array<std::size_t, 3>& triangles, double tolerance) const {
    for (const std::size_t t : triangles)
      for (int k = 0; k < 3; ++k)
        if (plane.height(triangles_[t][k]) > tolerance) return false;
    return true;
  }

  // An upper bound on the distance from every point of `piece` to the surface when the
  // surface's triangles in the plane (within `tolerance`) cover the piece's projection onto
  // it: the distance to the plane then bounds it, and is largest at a corner. +inf when they
  // do not cover it, or when the piece stands steeply on the plane.
  double covered_plane_bound(const std::array<Point, 3>& piece, const Plane& plane, double reach,
                             double tolerance) const {
    const Vector piece_normal = CGAL::cross_product(piece[1] - piece[0], piece[2] - piece[0]);
    const double piece_norm = std::sqrt(piece_normal.squared_length());
    if (!(std::abs(piece_normal * plane.normal) >= kCoverMinCosine * piece_norm)) return kInfinity;
    Polygon2 projected{plane.in_plane(piece[0]), plane.in_plane(piece[1]), plane.in_plane(piece[2])};
    if (area2(projected) < 0.0) std::swap(projected[1], projected[2]);
    const double projected_area = area2(projected);

    CGAL::Bbox_3 box = piece[0].bbox() + piece[1].bbox() + piece[2].bbox();
    box = CGAL::Bbox_3(box.xmin() - reach, box.ymin() - reach, box.zmin() - reach, box.xmax() + reach,
                       box.ymax() + reach, box.zmax() + reach);
    std::vector<Triangles::const_iterator> near;
    tree_.all_intersected_primitives(box, std::back_inserter(near));
    double covered = 0.0;
    for (const auto it : near) {
      const Triangle& s = *it;
      if (plane.height(s[0]) > tolerance || plane.height(s[1]) > tolerance || plane.height(s[2]) > tolerance) continue;
      std::array<Point2, 3> flat{plane.in_plane(s[0]), plane.in_plane(s[1]), plane.in_plane(s[2])};
      const double a = cross2(flat[0], flat[1], flat[2]);
      if (a == 0.0) continue;
      if (a < 0.0) std::swap(flat[1], flat[2]);
      covered += area2(clip(projected, flat));
    }
    // A closed surface's triangles do not overlap, so the areas add up to the projection's
    // exactly where they cover it; more than that means overlapping triangles: no verdict.
    if (std::abs(covered - projected_area) > kCoverAreaTolerance * projected_area) return kInfinity;
    return std::max({plane.height(piece[0]), plane.height(piece[1]), plane.height(piece[2])}) + tolerance;
  }

 private:
  Triangles triangles_;
  AabbTree tree_;
};

// A triangle of the measured surface, or a part of one, with what its corners see.
struct Piece {
  std::array<Point, 3> corner;
  std::array<Closest, 3> closest;
  double upper = kInfinity;  // bound on the distance of any of its points to the target
  bool tried_plane = false;
  bool operator<(const Piece& other) const { return upper < other.upper; }
};

// Whether corner k is the first of the piece's corners closest to its triangle.
bool first_at_its_triangle(const Piece& p, int k) {
  const std::size_t t = p.closest[k].triangle;
  return !((k > 0 && t == p.closest[0].triangle) || (k > 1 && t == p.closest[1].triangle));
}

// Every point of the piece is within the largest corner distance to any one triangle: the
// distance to a triangle is convex. The triangles tried are those the corners are closest to.
double corner_bound(const Target& target, const Piece& p) {
  double best = kInfinity;
  for (int k = 0; k < 3; ++k) {
    if (!first_at_its_triangle(p, k)) continue;
    const std::size_t t = p.closest[k].triangle;
    double worst = p.closest[k].distance;
    for (int i = 0; i < 3; ++i)
      if (i != k) worst = std::max(worst, target.distance(t, p.corner[i]));
    best = std::min(best, worst);
  }
  return best;
}

// Where the corners are closest to coplanar triangles that together cover the piece, the
// piece is as far as its farthest corner. This is what makes surfaces lying on each other
// cheap: a piece straddling two of the target's coplanar triangles is otherwise only bounded
// by subdividing it down to the error bound along their common edge.
double plane_bound(const Target& target, const Piece& p, double tolerance) {
  const std::array<std::size_t, 3> tri{p.closest[0].triangle, p.closest[1].triangle, p.closest[2].triangle};
  const double reach =
      std::max({p.closest[0].distance, p.closest[1].distance, p.closest[2].distance}) + tolerance;
  for (int k = 0; k < 3; ++k) {
    if (!first_at_its_triangle(p, k)) continue;
    const auto plane = target.plane(tri[k]);
    if (!plane || !target.within(*plane, tri, tolerance)) continue;
    const double bound = target.covered_plane_bound(p.corner, *plane, reach, tolerance);
    if (bound < kInfinity) return bound;
  }
  return kInfinity;
}

Vec3 to_vec(const Point& p) { return {p.x(), p.y(), p.z()}; }

// max over points of `from` of the distance to `to`, at most `error_bound` below it: the
// largest distance found at a corner, where pieces whose upper bound exceeds it by more than
// the error bound are subdivided, farthest first (Tang et al.'s scheme, as CGAL's
// bounded-error Hausdorff distance, with the coplanar cover bound added).
FarthestPoint one_sided(const TriSurface& from, const Target& to, double error_bound) {
  FarthestPoint found;
  const auto measure = [&](const Point& p) {
    const Closest c = to.closest(p);
    ++found.points;
    if (c.distance > found.distance) {
      found.distance = c.distance;
      found.at = to_vec(p);
    }
    return c;
  };
  // Only the triangles' corners: a mesh boundary keeps the interior points in its list.
  std::vector<Closest> at_point(from.points.size());
  std::vector<char> seen(from.points.size(), 0);
  for (const auto& t : from.triangles)
    for (const Index i : t)
      if (!seen[i]) {
        seen[i] = 1;
        at_point[i] = measure(Target::point(from.points[i]));
      }
  const double& lower = found.distance;
  // Coplanar within kCoplanarFraction of the bound.
  const double tolerance = kCoplanarFraction * error_bound;
  std::priority_queue<Piece> queue;
  const auto consider = [&](Piece&& p) {
    p.upper = corner_bound(to, p);
    if (p.upper > lower + error_bound) queue.push(std::move(p));
  };
  for (const auto& t : from.triangles) {
    Piece p;
    for (int k = 0; k < 3; ++k) {
      p.corner[k] = Target::point(from.points[t[k]]);
      p.closest[k] = at_point[t[k]];
    }
    consider(std::move(p));
  }
  while (!queue.empty() && queue.top().upper > lower + error_bound) {
    Piece p = queue.top();
    queue.pop();
    if (!p.tried_plane) {
      p.tried_plane = true;
      if (plane_bound(to, p, tolerance) <= lower + error_bound) continue;
    }
    const double size = std::max({CGAL::squared_distance(p.corner[0], p.corner[1]),
                                  CGAL::squared_distance(p.corner[1], p.corner[2]),
                                  CGAL::squared_distance(p.corner[2], p.corner[0])});
    // A piece smaller than the bound is within it of its corners: nothing left to split.
    if (std::sqrt(size) <= error_bound) continue;
    std::array<Point, 3> mid;
    std::array<Closest, 3> mid_closest;
    for (int k = 0; k < 3; ++k) {
      mid[k] = CGAL::midpoint(p.corner[k], p.corner[(k + 1) % 3]);
      mid_closest[k] = measure(mid[k]);
    }
    for (int k = 0; k < 3; ++k)
      consider({{p.corner[k], mid[k], mid[(k + 2) % 3]}, {p.closest[k], mid_closest[k], mid_closest[(k + 2) % 3]}});
    consider({mid, mid_closest});
  }
  return found;
}

// Barycentric grid of order n on the triangle, n even and no coarser than `spacing` along
// the longest edge: its corners, edge midpoints and interior points; plus the centroid.
void triangle_samples(const std::array<Vec3, 3>& t, double spacing, std::vector<Vec3>& out) {
  const double longest =
      std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
  int n = std::max(2, static_cast<int>(std::ceil(longest / spacing)));
  n += n % 2;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      out.push_back(t[0] + (t[1] - t[0]) * (double(i) / n) + (t[2] - t[0]) * (double(j) / n));
  out.push_back((t[0] + t[1] + t[2]) / 3.0);
}

}  // namespace

struct TriangulatedSurface::Tree {
  explicit Tree(const TriSurface& s) : target(s) {}
  Target target;
};

TriangulatedSurface::TriangulatedSurface(TriSurface surface) : surface_(std::move(surface)) {
  if (surface_.triangles.empty())
    throw std::invalid_argument("TriangulatedSurface: the surface has no triangles");
  tree_ = std::make_unique<Tree>(surface_);
}

TriangulatedSurface::~TriangulatedSurface() = default;

double TriangulatedSurface::distance(const Vec3& p) const {
  return tree_->target.closest(Target::point(p)).distance;
}

void TriangulatedSurface::sample(std::size_t part, double spacing, std::vector<Vec3>& out) const {
  const auto& t = surface_.triangles[part];
  triangle_samples({surface_.points[t[0]], surface_.points[t[1]], surface_.points[t[2]]}, spacing,
                   out);
}

FarthestPoint TriangulatedSurface::farthest_from(const TriSurface& from, double error_bound) const {
  return one_sided(from, tree_->target, error_bound);
}

HausdorffDistance hausdorff_distance(const TriSurface& a, const TriSurface& b, double error_bound) {
  const TriangulatedSurface ta(a), tb(b);
  return {tb.farthest_from(a, error_bound).distance, ta.farthest_from(b, error_bound).distance};
}

}  // namespace volmesh
