// Optimisation-based smoothing (Freitag and Ollivier-Gooch, as Stellar does it): the worst
// quality of a point's star is a non-smooth function of the point; ascend along the direction
// that raises all the worst tets at once (the shortest vector in the convex hull of their
// gradients), the step halved from a fraction of the star's shortest edge until the worst
// rises.
#include "smooth.hpp"

#include <algorithm>
#include <limits>

#include "exact.hpp"
#include "quality.hpp"

namespace volmesh::improve {

namespace {

constexpr int kMaxIterations = 12;
// Tets within this of the star's worst count as worst (the active set).
constexpr double kActiveBand = 1e-3;
// Finite-difference step, relative to the star's shortest edge.
constexpr double kDifferenceStep = 1e-6;
// A step moves the point at most this fraction of the star's shortest edge.
constexpr double kMaxStep = 0.5;
constexpr int kHalvings = 12;
// A move must raise the star's worst quality by this much: smaller gains are not worth a pass.
constexpr double kSmoothGain = 1e-4;
// Rounds of Gilbert's algorithm for the shortest vector in the hull of the gradients.
constexpr int kHullRounds = 64;

// The star of v, v's corner marked in each tet, worst tets first.
struct Star {
  std::vector<Tet> tets;
  std::vector<int> corner;
  double shortest = std::numeric_limits<double>::infinity();
};

double quality_at(const TetComplex& mesh, const Star& star, std::size_t i, const Vec3& p) {
  std::array<Vec3, 4> q;
  for (int k = 0; k < 4; ++k) q[k] = mesh.point(star.tets[i][k]);
  q[star.corner[i]] = p;
  return tet_quality(q[0], q[1], q[2], q[3]);
}

// The star's worst quality at p, or any value at most `floor` once it is known to be no more.
double worst_at(const TetComplex& mesh, const Star& star, const Vec3& p,
                double floor = kFlatQuality) {
  double q = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < star.tets.size() && q > floor; ++i)
    q = std::min(q, quality_at(mesh, star, i, p));
  return q;
}

// The direction's part that keeps the point in its plane or on its line.
Vec3 constrained(const TetComplex& mesh, Index v, const Vec3& d) {
  if (mesh.freedom(v) != Freedom::Slides) return d;
  const Slide& s = mesh.slide(v);
  if (s.kind == SlideKind::Line) {
    const Vec3 along = (s.corners[1] - s.corners[0]).normalized();
    return d.dot(along) * along;
  }
  const Vec3 n = (s.corners[1] - s.corners[0]).cross(s.corners[2] - s.corners[0]).normalized();
  return d - d.dot(n) * n;
}

// Forward differences from the quality q at p.
Vec3 gradient(const TetComplex& mesh, const Star& star, std::size_t i, const Vec3& p, double q,
              double h) {
  Vec3 g;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 plus = p;
    plus[axis] += h;
    g[axis] = (quality_at(mesh, star, i, plus) - q) / h;
  }
  return g;
}

// The shortest vector in the convex hull of the gradients (Gilbert's algorithm).
Vec3 shortest_in_hull(const std::vector<Vec3>& g) {
  Vec3 x = g.front();
  for (int round = 0; round < kHullRounds; ++round) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < g.size(); ++i)
      if (g[i].dot(x) < g[best].dot(x)) best = i;
    const Vec3 d = g[best] - x;
    const double dd = d.squaredNorm();
    if (!(dd > 0.0) || d.dot(x) >= 0.0) break;
    x += std::clamp(-x.dot(d) / dd, 0.0, 1.0) * d;
  }
  return x;
}

Star star_of(const TetComplex& mesh, Index v) {
  std::vector<Index> tets = mesh.star(v);
  std::stable_sort(tets.begin(), tets.end(),
                   [&](Index a, Index b) { return mesh.quality(a) < mesh.quality(b); });
  Star star;
  for (const Index t : tets) {
    const Tet& s = mesh.tet(t);
    star.tets.push_back(s);
    star.corner.push_back(static_cast<int>(std::find(s.begin(), s.end(), v) - s.begin()));
    for (const Index w : s)
      if (w != v) star.shortest = std::min(star.shortest, (mesh.point(w) - mesh.point(v)).norm());
  }
  return star;
}

// One ascent step from p (worst quality `worst`); false when none raises it.
bool ascend(const TetComplex& mesh, Index v, const Star& star, Vec3& p, double& worst) {
  const double h = kDifferenceStep * star.shortest;
  std::vector<Vec3> active;
  for (std::size_t i = 0; i < star.tets.size(); ++i) {
    const double q = quality_at(mesh, star, i, p);
    if (q <= worst + kActiveBand) active.push_back(constrained(mesh, v, gradient(mesh, star, i, p, q, h)));
  }
  if (active.empty()) return false;  // no quality to raise: NaN where points coincide
  const Vec3 d = shortest_in_hull(active);
  const double length = d.norm();
  if (!(length > 0.0)) return false;  // the worst tets pull against each other: optimal
  double slope = std::numeric_limits<double>::infinity();
  for (const Vec3& g : active) slope = std::min(slope, g.dot(d));
  if (!(slope > 0.0)) return false;
  double step = kMaxStep * star.shortest / length;
  for (int k = 0; k < kHalvings; ++k, step *= 0.5) {
    const Vec3 x = p + step * d;
    const double value = worst_at(mesh, star, x, worst);
    if (raises(value, worst)) {
      p = x;
      worst = value;
      return true;
    }
  }
  return false;
}

}  // namespace

bool smooth_point(TetComplex& mesh, Index v) {
  if (mesh.freedom(v) == Freedom::Pinned || mesh.star(v).empty()) return false;
  const Star star = star_of(mesh, v);
  const Vec3 start = mesh.point(v);
  Vec3 p = start;
  const double initial = worst_at(mesh, star, p);
  double worst = initial;
  for (int i = 0; i < kMaxIterations; ++i)
    if (!ascend(mesh, v, star, p, worst)) break;
  if (!(worst > initial + kSmoothGain)) return false;
  if (mesh.freedom(v) == Freedom::Slides && !stays_within(mesh.slide(v), p)) return false;
  for (std::size_t i = 0; i < star.tets.size(); ++i) {
    std::array<Vec3, 4> q;
    for (int k = 0; k < 4; ++k) q[k] = mesh.point(star.tets[i][k]);
    q[star.corner[i]] = p;
    if (!positive(q[0], q[1], q[2], q[3])) return false;
  }
  mesh.move(v, p);
  return true;
}

}  // namespace volmesh::improve
