#include "exact.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace volmesh::improve {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Point_3 cg(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

bool positive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return CGAL::orientation(cg(a), cg(b), cg(c), cg(d)) == CGAL::POSITIVE;
}

}  // namespace volmesh::improve
