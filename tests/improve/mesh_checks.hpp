#pragma once
// Checks of a tet mesh after a change: its boundary and interface triangles by coordinates,
// conformity, every tet positive and the volume, both exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "poor_meshes.hpp"

namespace volmesh::test {

using Triangle = std::array<std::array<double, 3>, 3>;

inline Triangle coordinates(const TetMesh& m, std::array<Index, 3> f) {
  // Rotated so that the smallest corner comes first: the same triangle reads the same.
  const auto at = [&](int k) {
    const Vec3& p = m.points[f[k]];
    return std::array<double, 3>{p.x(), p.y(), p.z()};
  };
  Triangle t{at(0), at(1), at(2)};
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

inline std::multiset<Triangle> boundary_triangles(const TetMesh& m) {
  std::multiset<Triangle> out;
  for (const auto& f : m.boundary_faces) out.insert(coordinates(m, f));
  return out;
}

// The faces between the two regions, each as region 1 sees it.
inline std::multiset<Triangle> interface_triangles(const TetMesh& m) {
  std::map<std::array<Index, 3>, std::pair<Index, std::array<Index, 3>>> seen;
  std::multiset<Triangle> out;
  for (Index c = 0; c < m.num_cells(); ++c)
    for (const auto& f : kTetFaces) {
      const std::array<Index, 3> loop{m.cells[c][f[0]], m.cells[c][f[1]], m.cells[c][f[2]]};
      auto key = loop;
      std::sort(key.begin(), key.end());
      const auto [it, fresh] = seen.emplace(key, std::make_pair(m.cell_region[c], loop));
      if (fresh || it->second.first == m.cell_region[c]) continue;
      out.insert(coordinates(m, m.cell_region[c] == 1 ? loop : it->second.second));
    }
  return out;
}

// Every face used by one or two tets, the ones used once exactly the boundary faces.
inline void expect_conforming(const TetMesh& m) {
  std::map<std::array<Index, 3>, int> uses;
  for (const auto& c : m.cells)
    for (const auto& f : kTetFaces) {
      std::array<Index, 3> key{c[f[0]], c[f[1]], c[f[2]]};
      std::sort(key.begin(), key.end());
      ++uses[key];
    }
  std::size_t once = 0;
  for (const auto& [face, n] : uses) {
    ASSERT_LE(n, 2);
    once += n == 1;
  }
  EXPECT_EQ(once, m.boundary_faces.size());
}

inline void expect_exactly_positive(const TetMesh& m) {
  for (Index c = 0; c < m.num_cells(); ++c)
    ASSERT_GT(sgn(exact_six_volume(m.points, m.cells[c])), 0) << "tet " << c;
}

inline mpq_class exact_volume(const TetMesh& m) {
  mpq_class sum = 0;
  for (const auto& c : m.cells) sum += exact_six_volume(m.points, c);
  return sum;
}

}  // namespace volmesh::test
