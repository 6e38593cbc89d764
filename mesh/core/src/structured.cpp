#include "volmesh/core/structured.hpp"

#include <algorithm>
#include <stdexcept>

#include "volmesh/core/geometry.hpp"

namespace volmesh {

namespace {

void check_counts(const std::array<Index, 3>& n) {
  const std::int64_t cells = std::int64_t(n[0]) * n[1] * n[2];
  const std::int64_t points = std::int64_t(n[0] + 1) * (n[1] + 1) * (n[2] + 1);
  if (n[0] < 1 || n[1] < 1 || n[2] < 1) throw std::invalid_argument("grid: counts must be >= 1");
  if (6 * cells > kMaxIndex || points > kMaxIndex)
    throw std::invalid_argument("grid: more cells than the 32-bit index range allows");
}

}  // namespace

HexMesh structured_hex_mesh(const Vec3& lo, const Vec3& hi, const std::array<Index, 3>& n) {
  check_counts(n);
  HexMesh m;
  const auto id = [&](Index i, Index j, Index k) { return i + (n[0] + 1) * (j + (n[1] + 1) * k); };
  m.points.reserve(std::size_t(n[0] + 1) * (n[1] + 1) * (n[2] + 1));
  for (Index k = 0; k <= n[2]; ++k)
    for (Index j = 0; j <= n[1]; ++j)
      for (Index i = 0; i <= n[0]; ++i) {
        const Vec3 t(double(i) / n[0], double(j) / n[1], double(k) / n[2]);
        m.points.push_back(lo + (hi - lo).cwiseProduct(t));
      }
  for (Index k = 0; k < n[2]; ++k)
    for (Index j = 0; j < n[1]; ++j)
      for (Index i = 0; i < n[0]; ++i)
        m.cells.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                           id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                           id(i, j + 1, k + 1)});
  m.cell_region.assign(m.cells.size(), 1);
  m.tag_names = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  // Boundary quads: the hex faces that lie on the box sides, in kHexFaces orientation.
  for (Index k = 0; k < n[2]; ++k)
    for (Index j = 0; j < n[1]; ++j)
      for (Index i = 0; i < n[0]; ++i) {
        const auto& h = m.cells[i + n[0] * (j + n[1] * k)];
        const auto quad = [&](int f) {
          return std::array<Index, 4>{h[kHexFaces[f][0]], h[kHexFaces[f][1]], h[kHexFaces[f][2]],
                                      h[kHexFaces[f][3]]};
        };
        const std::array<std::pair<bool, int>, 6> sides{{{i == 0, 5},
                                                         {i == n[0] - 1, 3},
                                                         {j == 0, 2},
                                                         {j == n[1] - 1, 4},
                                                         {k == 0, 0},
                                                         {k == n[2] - 1, 1}}};
        for (int s = 0; s < 6; ++s)
          if (sides[s].first) {
            m.boundary_faces.push_back(quad(sides[s].second));
            m.boundary_tag.push_back(s);
          }
      }
  return m;
}

TetMesh kuhn_tet_mesh(const Vec3& lo, const Vec3& hi, const std::array<Index, 3>& n) {
  const HexMesh hex = structured_hex_mesh(lo, hi, n);
  // Corner of the hex at bit offsets (x, y, z) in VTK order.
  constexpr std::array<int, 8> corner_of_bits{0, 1, 3, 2, 4, 5, 7, 6};
  std::array<int, 3> axes{0, 1, 2};
  TetMesh t;
  t.points = hex.points;
  t.tag_names = hex.tag_names;
  for (const auto& h : hex.cells) {
    std::sort(axes.begin(), axes.end());
    do {
      // Path 000 -> 111 adding one axis at a time: one of the 6 Kuhn simplices.
      std::array<Index, 4> tet;
      int bits = 0;
      tet[0] = h[corner_of_bits[0]];
      for (int s = 0; s < 3; ++s) {
        bits |= 1 << axes[s];
        tet[s + 1] = h[corner_of_bits[bits]];
      }
      if (tet_volume(t.points[tet[0]], t.points[tet[1]], t.points[tet[2]], t.points[tet[3]]) < 0)
        std::swap(tet[2], tet[3]);
      t.cells.push_back(tet);
    } while (std::next_permutation(axes.begin(), axes.end()));
  }
  t.cell_region.assign(t.cells.size(), 1);
  // Boundary triangles: tet faces whose three vertices lie on the same side of the box,
  // found from the grid indices so that no coordinate comparison is involved.
  const auto grid_index = [&](Index v, int axis) {
    const Index nx = n[0] + 1, ny = n[1] + 1;
    return axis == 0 ? v % nx : axis == 1 ? (v / nx) % ny : v / (nx * ny);
  };
  for (const auto& tet : t.cells)
    for (const auto& lf : kTetFaces) {
      const std::array<Index, 3> tri{tet[lf[0]], tet[lf[1]], tet[lf[2]]};
      for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
          const Index plane = side == 0 ? 0 : n[axis];
          if (std::all_of(tri.begin(), tri.end(),
                          [&](Index v) { return grid_index(v, axis) == plane; })) {
            t.boundary_faces.push_back(tri);
            t.boundary_tag.push_back(2 * axis + side);
          }
        }
    }
  return t;
}

}  // namespace volmesh
