#include "nesting.hpp"

#include <cmath>
#include <numbers>

namespace volmesh::tet::front {

double winding_number(const std::vector<Vec3>& points,
                      const std::vector<std::array<Index, 3>>& triangles, const Vec3& p) {
  // Van Oosterom and Strackee's solid angle of each triangle seen from p.
  double sum = 0.0;
  for (const auto& t : triangles) {
    const Vec3 a = points[t[0]] - p, b = points[t[1]] - p, c = points[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    sum += 2.0 * std::atan2(num, den);
  }
  return sum / (4.0 * std::numbers::pi);
}

std::vector<Index> parents(const std::vector<Vec3>& points,
                           const std::vector<std::vector<std::array<Index, 3>>>& surfaces) {
  const Index n = static_cast<Index>(surfaces.size());
  // holds[s][t]: surface s holds surface t.
  std::vector<std::vector<char>> holds(n, std::vector<char>(n, 0));
  std::vector<int> depth(n, 0);
  for (Index s = 0; s < n; ++s)
    for (Index t = 0; t < n; ++t)
      if (s != t && std::abs(winding_number(points, surfaces[s],
                                            points[surfaces[t].front()[0]])) > 0.5) {
        holds[s][t] = 1;
        ++depth[t];
      }
  std::vector<Index> parent(n, kNoIndex);
  for (Index t = 0; t < n; ++t)
    for (Index s = 0; s < n; ++s)
      if (holds[s][t] && (parent[t] == kNoIndex || depth[s] > depth[parent[t]])) parent[t] = s;
  return parent;
}

}  // namespace volmesh::tet::front
