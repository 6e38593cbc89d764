#include "volmesh/domain/outer_boundary.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include "volmesh/domain/analytic.hpp"
#include "volmesh/domain/analytic_closest.hpp"

namespace volmesh {
namespace {

// project_along_normals, in fractions of the domain's bounding-box diagonal: the first search
// reaches kFirstReach either way and grows by kReachGrowth until it finds the boundary; the
// iteration stops when a step moves the point by at most kSettled (rounding), or after
// kMaxSteps; each later search reaches twice the distance found plus kReachSlack.
constexpr double kFirstReach = 0.01;
constexpr double kReachGrowth = 4.0;
constexpr double kSettled = 1e-14;
constexpr int kMaxSteps = 50;
constexpr double kReachSlack = 1e-9;
// The step off a surface point that tells which regions lie on its two sides (analytic
// domains): far above rounding, far below any feature of a domain.
constexpr double kSideStep = 1e-9;

bool separates_from_outside(const Crossing& c) {
  return c.before != c.after && (c.before == 0 || c.after == 0);
}

// The outer-boundary crossing nearest to p on the line p ± reach·n.
std::optional<Crossing> nearest_outer_crossing(const Domain& domain, const Vec3& p,
                                               const Vec3& n, double reach) {
  std::optional<Crossing> best;
  for (const Crossing& c : domain.crossings(p - reach * n, p + reach * n))
    if (separates_from_outside(c) && (!best || std::abs(c.t - 0.5) < std::abs(best->t - 0.5)))
      best = c;
  return best;
}

// Whether a point of a primitive's surface lies on the outer boundary: the region is 0 on
// exactly one side of it.
bool on_outer_boundary(const Domain& domain, const Vec3& q, const Vec3& normal, double step) {
  return (domain.region(q + step * normal) == 0) != (domain.region(q - step * normal) == 0);
}

// Whether a point of a primitive's surface lies on the closure of the outer boundary. On an
// edge of the boundary where two primitives meet at a reflex angle (the circle where the
// box's top meets the cylinder's side in builtin:primitives) the test along the normal alone
// fails: one side is the other primitive's inside. The surface beside the edge is boundary,
// and one of four tangent steps lands on it: a half-plane of the tangent plane holds one of
// ±t1, ±t2 strictly inside.
bool on_closed_outer_boundary(const Domain& domain, const Vec3& q, const Vec3& normal,
                              double step) {
  if (on_outer_boundary(domain, q, normal, step)) return true;
  const Vec3 t1 = normal.unitOrthogonal(), t2 = normal.cross(t1);
  constexpr double kTangentSteps = 2.0;  // beyond the normal step, so the edge is left behind
  for (const Vec3& t : {t1, Vec3(-t1), t2, Vec3(-t2)})
    if (on_outer_boundary(domain, q + kTangentSteps * step * t, normal, step)) return true;
  return false;
}

Vec3 closest_on_analytic(const AnalyticDomain& domain, const Vec3& p, double step) {
  std::optional<Vec3> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (const Primitive& prim : domain.primitives()) {
    const SurfacePoint s = closest_surface_point(prim, p);
    const double d = (s.point - p).squaredNorm();
    if (d < best_distance && on_closed_outer_boundary(domain, s.point, s.normal, step)) {
      best = s.point;
      best_distance = d;
    }
  }
  return best ? *best : project_along_normals(domain, p);
}

}  // namespace

Vec3 project_along_normals(const Domain& domain, const Vec3& p) {
  const double size = domain.bounds().size().norm();
  Vec3 n = domain.normal(p);
  std::optional<Vec3> q;
  double reach = kFirstReach * size;
  for (int step = 0; step < kMaxSteps;) {
    const std::optional<Crossing> c = nearest_outer_crossing(domain, p, n, reach);
    if (!c) {
      if (reach > size) break;
      reach *= kReachGrowth;
      continue;
    }
    const bool settled = q && (c->point - *q).norm() <= kSettled * size;
    q = c->point;
    n = c->normal;
    if (settled) break;
    reach = 2.0 * (*q - p).norm() + kReachSlack * size;
    ++step;
  }
  return q ? *q : p;
}

std::function<Vec3(const Vec3&)> outer_boundary_map(const Domain& domain) {
  const Domain* d = &domain;
  if (const auto* analytic = dynamic_cast<const AnalyticDomain*>(d)) {
    const double step = kSideStep * domain.bounds().size().norm();
    return [analytic, step](const Vec3& p) { return closest_on_analytic(*analytic, p, step); };
  }
  return [d](const Vec3& p) { return project_along_normals(*d, p); };
}

}  // namespace volmesh
