#pragma once
// The front's output against its input surfaces: valid as volmesh check has it, the enclosed
// volume, and every input triangle a face of a tet.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/tet_front/front.hpp"

namespace volmesh::tet::test {

// The volume the outermost surfaces enclose, from their triangles.
inline double enclosed_volume(const std::vector<ProjectionSurface>& surfaces) {
  double v = 0.0;
  for (const ProjectionSurface& s : surfaces) {
    if (!s.outermost) continue;
    for (const auto& t : s.surface.triangles)
      v += s.surface.points[t[0]].dot(s.surface.points[t[1]].cross(s.surface.points[t[2]])) / 6.0;
  }
  return v;
}

// Valid (volmesh check's validity), the volume enclosed, and every input triangle a face of
// one tet of the mesh on its inner side.
inline void expect_valid(const std::vector<ProjectionSurface>& surfaces, const FrontResult& r) {
  const ValidityReport v = check_validity(to_poly_mesh(r.mesh));
  EXPECT_TRUE(v.valid()) << (v.problems.empty() ? "" : v.problems.front());
  const double enclosed = enclosed_volume(surfaces);
  EXPECT_NEAR(v.total_volume, enclosed, 1e-12 * enclosed);
  std::set<std::array<Index, 3>> faces;
  for (const auto& c : r.mesh.cells)
    for (const auto& f : kTetFaces) {
      std::array<Index, 3> t{c[f[0]], c[f[1]], c[f[2]]};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      faces.insert(t);
    }
  Index first = 0;
  for (const ProjectionSurface& s : surfaces) {
    for (const auto& t : s.surface.triangles) {
      std::array<Index, 3> g{first + t[0], first + t[1], first + t[2]};
      std::rotate(g.begin(), std::min_element(g.begin(), g.end()), g.end());
      EXPECT_TRUE(faces.count(g)) << s.name << " triangle not kept";
    }
    first += s.surface.num_points();
  }
}

}  // namespace volmesh::tet::test
