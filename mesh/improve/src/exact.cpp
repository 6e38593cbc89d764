#include "exact.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace volmesh::improve {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Point_3 cg(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

bool positive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // A candidate computed from a flat tet (a step along an infinite gradient, a circumcentre)
  // can be NaN or infinite: no tet with such a corner is written, and the exact test has no
  // number for it.
  if (!(a.allFinite() && b.allFinite() && c.allFinite() && d.allFinite())) return false;
  return CGAL::orientation(cg(a), cg(b), cg(c), cg(d)) == CGAL::POSITIVE;
}

}  // namespace volmesh::improve
