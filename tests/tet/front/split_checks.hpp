#pragma once
// The checks of a front mesh of one outermost surface that a fallback may have split: valid
// (positive volumes, conformity), the enclosed volume to 1e-12, and each input triangle either
// a boundary face or counted as split.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/tet_front/front.hpp"

namespace volmesh::tet::test {

inline double surface_volume(const TriSurface& s) {
  double v = 0.0;
  for (const auto& t : s.triangles)
    v += s.points[t[0]].dot(s.points[t[1]].cross(s.points[t[2]])) / 6.0;
  return v;
}

inline void expect_valid_with_splits(const TriSurface& surface, const FrontResult& r) {
  const ValidityReport v = check_validity(to_poly_mesh(r.mesh));
  EXPECT_TRUE(v.valid()) << (v.problems.empty() ? "" : v.problems.front());
  const double enclosed = surface_volume(surface);
  EXPECT_NEAR(v.total_volume, enclosed, 1e-12 * enclosed);
  std::set<std::array<Index, 3>> boundary;
  for (auto f : r.mesh.boundary_faces) {
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    boundary.insert(f);
  }
  long long whole = 0;
  for (auto t : surface.triangles) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    whole += boundary.count(t);
  }
  EXPECT_EQ(whole + r.stats.split_boundary_faces, static_cast<long long>(surface.triangles.size()));
}

}  // namespace volmesh::tet::test
