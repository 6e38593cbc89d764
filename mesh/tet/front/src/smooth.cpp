#include "smooth.hpp"

#include <algorithm>
#include <limits>

#include "min_sine.hpp"
#include "predicates.hpp"

namespace volmesh::tet::front {

namespace {

constexpr int kAscentSteps = 6;
// The worst tets: those within this of the star's minimum quality.
constexpr double kActiveBand = 1e-3;
constexpr int kMaxDirections = 4;
// Line search: the first step is this fraction of the star's shortest edge, then halved.
constexpr double kFirstStep = 0.25;
constexpr int kHalvings = 8;
// Finite-difference step, relative to the star's shortest edge.
constexpr double kDifferenceStep = 1e-6;
// A move must raise the star's minimum quality by more than this (rounding noise never counts).
constexpr double kMinGain = 1e-9;

// The star of v with v's corner marked, so that its quality can be evaluated at any point.
struct Star {
  std::vector<Tet> tets;
  std::vector<int> corner;  // where v stands in each tet
  double shortest = std::numeric_limits<double>::max();
};

double tet_quality(const LiveMesh& mesh, const Tet& t, int corner, const Vec3& p) {
  std::array<Vec3, 4> q{mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3])};
  q[corner] = p;
  return min_sine(q[0], q[1], q[2], q[3]);
}

// The star's minimum quality with v at p, or any value at most `floor` once it is known to be
// no more (the worst tets come first, so that poor points are told after a few).
double star_quality(const LiveMesh& mesh, const Star& star, const Vec3& p,
                    double floor = -std::numeric_limits<double>::max()) {
  double q = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < star.tets.size() && q > floor; ++i)
    q = std::min(q, tet_quality(mesh, star.tets[i], star.corner[i], p));
  return q;
}

Vec3 gradient(const LiveMesh& mesh, const Tet& t, int corner, const Vec3& p, double step) {
  Vec3 g;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 plus = p, minus = p;
    plus[axis] += step;
    minus[axis] -= step;
    g[axis] = (tet_quality(mesh, t, corner, plus) - tet_quality(mesh, t, corner, minus)) / (2 * step);
  }
  return g;
}

// The best point along the directions from p, if it beats `quality`.
bool line_search(const LiveMesh& mesh, const Star& star, const std::vector<Vec3>& directions,
                 Vec3& p, double& quality) {
  Vec3 best = p;
  double best_quality = quality + kMinGain;
  for (const Vec3& d : directions) {
    double step = kFirstStep * star.shortest;
    for (int k = 0; k <= kHalvings; ++k, step *= 0.5) {
      const Vec3 x = p + step * d;
      const double q = star_quality(mesh, star, x, best_quality);
      if (q > best_quality) {
        best = x;
        best_quality = q;
      }
    }
  }
  if (best == p) return false;
  p = best;
  quality = best_quality;
  return true;
}

bool star_positive(const LiveMesh& mesh, const Star& star, const Vec3& p) {
  for (std::size_t i = 0; i < star.tets.size(); ++i) {
    std::array<Vec3, 4> q{mesh.point(star.tets[i][0]), mesh.point(star.tets[i][1]),
                          mesh.point(star.tets[i][2]), mesh.point(star.tets[i][3])};
    q[star.corner[i]] = p;
    if (!positive(q[0], q[1], q[2], q[3])) return false;
  }
  return true;
}

}  // namespace

bool smooth_node(LiveMesh& mesh, Index v) {
  if (!mesh.movable(v) || mesh.incident(v).empty()) return false;
  Star star;
  Vec3 centroid = Vec3::Zero();
  std::vector<Index> neighbours;
  std::vector<Index> tets = mesh.incident(v);
  std::stable_sort(tets.begin(), tets.end(),
                   [&](Index a, Index b) { return mesh.quality(a) < mesh.quality(b); });
  for (const Index t : tets) {
    const Tet& s = mesh.tet(t);
    star.tets.push_back(s);
    star.corner.push_back(static_cast<int>(std::find(s.begin(), s.end(), v) - s.begin()));
    for (const Index w : s)
      if (w != v) {
        neighbours.push_back(w);
        star.shortest = std::min(star.shortest, (mesh.point(w) - mesh.point(v)).norm());
      }
  }
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  for (const Index w : neighbours) centroid += mesh.point(w);
  centroid /= static_cast<double>(neighbours.size());

  const Vec3 start = mesh.point(v);
  Vec3 p = start;
  double quality = star_quality(mesh, star, p);
  const double laplacian = star_quality(mesh, star, centroid);
  if (laplacian > quality + kMinGain) {
    p = centroid;
    quality = laplacian;
  }
  for (int step = 0; step < kAscentSteps; ++step) {
    std::vector<Vec3> directions;
    Vec3 sum = Vec3::Zero();
    for (std::size_t i = 0; i < star.tets.size(); ++i) {
      if (tet_quality(mesh, star.tets[i], star.corner[i], p) > quality + kActiveBand) continue;
      const Vec3 g = gradient(mesh, star.tets[i], star.corner[i], p, kDifferenceStep * star.shortest);
      const double norm = g.norm();
      if (!(norm > 0.0)) continue;
      sum += g / norm;
      if (static_cast<int>(directions.size()) < kMaxDirections - 1) directions.push_back(g / norm);
    }
    if (directions.size() > 1 && sum.norm() > 0.0) directions.push_back(sum.normalized());
    if (directions.empty() || !line_search(mesh, star, directions, p, quality)) break;
  }
  if (p == start || !star_positive(mesh, star, p)) return false;
  mesh.move(v, p);
  return true;
}

}  // namespace volmesh::tet::front
