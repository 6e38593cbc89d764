// Horizons of a block must not cross: the difference of two piecewise-linear graphs is
// linear between the vertices of both and the crossings of their edges seen from above, so
// it is enough to compare the heights there, each with one exact orientation test.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <sstream>

#include "layered_model.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh::layers {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;
using Point3 = Kernel::Point_3;

int sign(CGAL::Orientation o) { return o == CGAL::POSITIVE ? 1 : o == CGAL::NEGATIVE ? -1 : 0; }

// Whether both sheets project to the same triangles: then the vertices tell it all.
bool same_projection(const GraphSheet& a, const GraphSheet& b) {
  if (a.triangles != b.triangles || a.points.size() != b.points.size()) return false;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    if (a.points[i][a.u] != b.points[i][b.u] || a.points[i][a.v] != b.points[i][b.v]) return false;
  return true;
}

}  // namespace

void check_order(const GraphSheet& lower, const GraphSheet& upper, const std::string& model) {
  const auto fail = [&](const Vec3& at) {
    std::ostringstream s;
    s.precision(9);
    s << model << ": horizons '" << lower.name << "' and '" << upper.name
      << "' cross (the layer between them would have a negative thickness) near (" << at.x() << ", "
      << at.y() << ", " << at.z() << ")";
    throw InputError(s.str());
  };
  // Used vertices only: a sheet's unused points may lie anywhere.
  const auto vertices = [](const GraphSheet& s) {
    std::vector<char> used(s.points.size(), 0);
    for (const auto& t : s.triangles)
      for (Index c : t) used[c] = 1;
    return used;
  };
  const std::vector<char> lower_used = vertices(lower), upper_used = vertices(upper);
  for (std::size_t i = 0; i < lower.points.size(); ++i)
    if (lower_used[i] && upper.side(lower.points[i]) > 0) fail(lower.points[i]);
  for (std::size_t i = 0; i < upper.points.size(); ++i)
    if (upper_used[i] && lower.side(upper.points[i]) < 0) fail(upper.points[i]);
  if (same_projection(lower, upper)) return;

  const int u = lower.u, v = lower.v;
  const auto p2 = [&](const Vec3& p) { return Point2(p[u], p[v]); };
  const auto p3 = [](const Vec3& p) { return Point3(p.x(), p.y(), p.z()); };
  for (std::size_t t = 0; t < lower.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index other = lower.across[t][k];
      if (other != kNoIndex && other < static_cast<Index>(t)) continue;  // each edge once
      const Vec3& a = lower.points[lower.triangles[t][k]];
      const Vec3& b = lower.points[lower.triangles[t][(k + 1) % 3]];
      upper.for_each_near(a.cwiseMin(b), a.cwiseMax(b), [&](Index s) {
        for (int m = 0; m < 3; ++m) {
          const Vec3& c = upper.points[upper.triangles[s][m]];
          const Vec3& d = upper.points[upper.triangles[s][(m + 1) % 3]];
          const int abc = sign(CGAL::orientation(p2(a), p2(b), p2(c)));
          const int abd = sign(CGAL::orientation(p2(a), p2(b), p2(d)));
          const int cda = sign(CGAL::orientation(p2(c), p2(d), p2(a)));
          const int cdb = sign(CGAL::orientation(p2(c), p2(d), p2(b)));
          // Seen from above the edges cross properly; the upper one must pass above.
          if (abc * abd >= 0 || cda * cdb >= 0) continue;
          if (sign(CGAL::orientation(p3(a), p3(b), p3(c), p3(d))) * abc < 0) {
            // Where the projections cross, on the lower edge.
            const Vec3 e = b - a, f = d - c;
            const double den = e[u] * f[v] - e[v] * f[u];
            const double r = ((c[u] - a[u]) * f[v] - (c[v] - a[v]) * f[u]) / den;
            fail(a + r * e);
          }
        }
      });
    }
}

}  // namespace volmesh::layers
