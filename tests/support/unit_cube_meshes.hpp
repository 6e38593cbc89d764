#pragma once
// The unit cube split in the classic ways: fixtures for the core, quality and I/O tests.
#include <algorithm>
#include <array>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/poly_mesh.hpp"

namespace volmesh::test {

// Unit cube corners in VTK hex order.
inline std::vector<Vec3> unit_cube_corners() {
  return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
}

// 5 tets: four corner tets and the central regular one.
inline TetMesh unit_cube_5_tets() {
  TetMesh m;
  m.points = unit_cube_corners();
  m.cells = {{0, 1, 3, 4}, {1, 2, 3, 6}, {1, 4, 5, 6}, {3, 6, 7, 4}, {1, 3, 4, 6}};
  m.cell_region.assign(5, 1);
  return m;
}

// 24 tets: each of the 6 faces split into 4 triangles around its centre, coned to the
// cube centre.
inline TetMesh unit_cube_24_tets() {
  TetMesh m;
  m.points = unit_cube_corners();
  m.points.push_back({0.5, 0.5, 0.5});
  const Index centre = 8;
  for (const auto& f : kHexFaces) {
    Vec3 c = Vec3::Zero();
    for (int v : f) c += m.points[v] / 4.0;
    m.points.push_back(c);
    const Index fc = static_cast<Index>(m.points.size()) - 1;
    for (int k = 0; k < 4; ++k)  // outward triangle (f[k], f[k+1], fc) plus the centre
      m.cells.push_back({f[k], fc, f[(k + 1) % 4], centre});
  }
  m.cell_region.assign(m.cells.size(), 1);
  return m;
}

inline HexMesh unit_cube_hex() {
  HexMesh m;
  m.points = unit_cube_corners();
  m.cells = {{0, 1, 2, 3, 4, 5, 6, 7}};
  m.cell_region = {1};
  return m;
}

// The unit cube next to four half-size cubes filling [1,1.5]x[0,1]x[0,1], as an octree
// makes it: the big cube's +x side is split into 4 faces, one shared with each small cell,
// and its other faces list the mid-edge vertices on x = 1, so every cell is closed.
// Cells: 0 is the big cube (region 1), 1-4 the small ones (region 2 when two_regions).
inline PolyMesh big_cube_next_to_four_small(bool two_regions = false) {
  PolyMesh m;
  const auto point = [&](double x, double y, double z) {
    const Vec3 p(x, y, z);
    for (Index i = 0; i < m.num_points(); ++i)
      if (m.points[i] == p) return i;
    m.points.push_back(p);
    return m.num_points() - 1;
  };
  // Each cell as outward loops; a face seen from two cells is stored once.
  std::vector<std::vector<std::vector<Index>>> cells(5);
  const double h = 0.5;
  auto& big = cells[0];
  big.push_back({point(0, 0, 0), point(0, 0, 1), point(0, 1, 1), point(0, 1, 0)});
  big.push_back({point(0, 0, 0), point(1, 0, 0), point(1, 0, h), point(1, 0, 1), point(0, 0, 1)});
  big.push_back({point(0, 1, 0), point(0, 1, 1), point(1, 1, 1), point(1, 1, h), point(1, 1, 0)});
  big.push_back({point(0, 0, 0), point(0, 1, 0), point(1, 1, 0), point(1, h, 0), point(1, 0, 0)});
  big.push_back({point(0, 0, 1), point(1, 0, 1), point(1, h, 1), point(1, 1, 1), point(0, 1, 1)});
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j) {
      auto& c = cells[1 + j + 2 * k];
      const double y = j * h, z = k * h, x0 = 1, x1 = 1 + h;
      big.push_back({point(x0, y, z), point(x0, y + h, z), point(x0, y + h, z + h), point(x0, y, z + h)});
      c.push_back({point(x0, y, z), point(x0, y, z + h), point(x0, y + h, z + h), point(x0, y + h, z)});
      c.push_back({point(x1, y, z), point(x1, y + h, z), point(x1, y + h, z + h), point(x1, y, z + h)});
      c.push_back({point(x0, y, z), point(x1, y, z), point(x1, y, z + h), point(x0, y, z + h)});
      c.push_back({point(x0, y + h, z), point(x0, y + h, z + h), point(x1, y + h, z + h), point(x1, y + h, z)});
      c.push_back({point(x0, y, z), point(x0, y + h, z), point(x1, y + h, z), point(x1, y, z)});
      c.push_back({point(x0, y, z + h), point(x1, y, z + h), point(x1, y + h, z + h), point(x0, y + h, z + h)});
    }
  const Index tag = m.tag_index("walls");
  std::vector<std::pair<std::vector<Index>, Index>> seen;  // sorted key -> face
  for (Index c = 0; c < 5; ++c)
    for (const auto& loop : cells[c]) {
      std::vector<Index> key = loop;
      std::sort(key.begin(), key.end());
      auto it = std::find_if(seen.begin(), seen.end(), [&](const auto& s) { return s.first == key; });
      if (it != seen.end()) {
        m.neighbour[it->second] = c;
        m.face_tag[it->second] = kNoIndex;
      } else {
        seen.emplace_back(key, m.add_face(loop, c, kNoIndex, tag));
      }
    }
  m.cell_region = {1, 1, 1, 1, 1};
  if (two_regions) std::fill(m.cell_region.begin() + 1, m.cell_region.end(), 2);
  return m;
}

}  // namespace volmesh::test
