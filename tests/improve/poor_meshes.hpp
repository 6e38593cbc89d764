#pragma once
// Poor tet meshes of the unit cube for the improver: an n³ grid of cubes, each split into the
// six tets around its diagonal, the points then jittered (deterministically) so that slivers
// and caps appear; optionally two regions (x < 1/2 and x > 1/2).
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <vector>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh::test {

inline double six_volume(const std::vector<Vec3>& p, const std::array<Index, 4>& t) {
  return (p[t[1]] - p[t[0]]).dot((p[t[2]] - p[t[0]]).cross(p[t[3]] - p[t[0]]));
}

// det(b - a, c - a, d - a) in rationals: the doubles as they are, exactly.
inline mpq_class exact_six_volume(const std::vector<Vec3>& p, const std::array<Index, 4>& t) {
  std::array<std::array<mpq_class, 3>, 3> m;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) m[r][k] = mpq_class(p[t[r + 1]][k]) - mpq_class(p[t[0]][k]);
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// The faces used by one tet, outward, tagged 0 ("boundary").
inline void add_boundary(TetMesh& m) {
  std::map<std::array<Index, 3>, std::pair<int, std::array<Index, 3>>> faces;
  for (const auto& c : m.cells)
    for (const auto& f : kTetFaces) {
      const std::array<Index, 3> loop{c[f[0]], c[f[1]], c[f[2]]};
      auto key = loop;
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      ++entry.first;
      entry.second = loop;
    }
  m.boundary_faces.clear();
  m.boundary_tag.clear();
  for (const auto& [key, entry] : faces)
    if (entry.first == 1) {
      m.boundary_faces.push_back(entry.second);
      m.boundary_tag.push_back(0);
    }
  m.tag_names = {"boundary"};
}

struct PoorCubeOptions {
  int n = 5;
  double jitter = 0.4;       // of the grid step, for interior points
  double face_jitter = 0.0;  // of the grid step, in their face's plane, for face points
  bool two_regions = false;
  unsigned seed = 7;
};

inline TetMesh poor_cube(const PoorCubeOptions& o) {
  TetMesh m;
  const int n = o.n;
  const double h = 1.0 / n;
  const auto id = [&](int i, int j, int k) { return static_cast<Index>((i * (n + 1) + j) * (n + 1) + k); };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) m.points.emplace_back(i * h, j * h, k * h);
  constexpr std::array<std::array<int, 3>, 6> kAxisOrders{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const auto& order : kAxisOrders) {
          std::array<int, 3> at{i, j, k};
          std::array<Index, 4> t;
          t[0] = id(at[0], at[1], at[2]);
          for (int s = 0; s < 3; ++s) {
            ++at[order[s]];
            t[s + 1] = id(at[0], at[1], at[2]);
          }
          if (six_volume(m.points, t) < 0) std::swap(t[0], t[1]);
          m.cells.push_back(t);
          m.cell_region.push_back(o.two_regions && i >= n / 2 ? 2 : 1);
        }
  add_boundary(m);
  // Jitter, each move halved until the point's tets stay clearly positive.
  std::vector<std::vector<Index>> star(m.points.size());
  for (Index c = 0; c < m.num_cells(); ++c)
    for (const Index v : m.cells[c]) star[v].push_back(c);
  std::mt19937 random(o.seed);
  const auto uniform = [&] { return 2.0 * (random() / 4294967296.0) - 1.0; };
  const double min_volume = 1e-3 * h * h * h;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const std::array<int, 3> at{i, j, k};
        int on_sides = 0, side_axis = -1;
        for (int a = 0; a < 3; ++a)
          if (at[a] == 0 || at[a] == n) ++on_sides, side_axis = a;
        // Interface points (x = 1/2) stay, so that the regions keep their shapes.
        const bool interface = o.two_regions && i == n / 2;
        const double amount = on_sides == 0 ? o.jitter : on_sides == 1 ? o.face_jitter : 0.0;
        Vec3 d(uniform(), uniform(), uniform());
        if (amount == 0.0 || interface) continue;
        if (side_axis >= 0) d[side_axis] = 0.0;
        d *= amount * h;
        const Index v = id(i, j, k);
        const Vec3 home = m.points[v];
        for (int tries = 0; tries < 4; ++tries, d *= 0.5) {
          m.points[v] = home + d;
          const bool ok = std::all_of(star[v].begin(), star[v].end(), [&](Index c) {
            return six_volume(m.points, m.cells[c]) > min_volume;
          });
          if (ok) break;
          m.points[v] = home;
        }
      }
  return m;
}

}  // namespace volmesh::test
