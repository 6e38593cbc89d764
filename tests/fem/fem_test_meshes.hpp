#pragma once
// Meshes of the unit cube for the finite-element tests: structured tets and hexes, an octree
// checkerboard with hanging faces, a grid cut by a plane into polyhedral pieces (two
// regions), and a smooth warp that makes faces non-planar while keeping the cube.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "volmesh/core/cell_soup.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/structured.hpp"

namespace volmesh::test {

inline PolyMesh kuhn_cube(Index n) {
  return to_poly_mesh(kuhn_tet_mesh(Vec3::Zero(), Vec3::Ones(), {n, n, n}));
}
inline PolyMesh hex_cube(Index n) {
  return to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {n, n, n}));
}

// Tags every boundary face of a mesh of the unit cube by its side: xmin … zmax.
inline void tag_cube_sides(PolyMesh& mesh) {
  mesh.tag_names = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!mesh.is_boundary(f)) continue;
    Vec3 c = Vec3::Zero();
    for (Index v : mesh.face(f)) c += mesh.points[v];
    c /= static_cast<double>(mesh.face(f).size());
    for (int axis = 0; axis < 3; ++axis) {
      if (std::abs(c[axis]) < 1e-12) mesh.face_tag[f] = 2 * axis;
      if (std::abs(c[axis] - 1.0) < 1e-12) mesh.face_tag[f] = 2 * axis + 1;
    }
  }
}

// Removes the points no face uses, renumbering the others in order.
inline void drop_unused_points(PolyMesh& mesh) {
  std::vector<Index> renumber(mesh.num_points(), kNoIndex);
  for (Index v : mesh.face_vertices) renumber[v] = 0;
  std::vector<Vec3> kept;
  for (Index p = 0; p < mesh.num_points(); ++p)
    if (renumber[p] == 0) {
      renumber[p] = static_cast<Index>(kept.size());
      kept.push_back(mesh.points[p]);
    }
  for (Index& v : mesh.face_vertices) v = renumber[v];
  mesh.points = std::move(kept);
}

// n³ cubes; those with i+j+k odd are split into 8, the others keep their size and see a
// split neighbour through every face: 24 quads (4 per side), 26 vertices, as an octree cell
// whose six neighbours are all finer.
inline PolyMesh octree_checkerboard(Index n) {
  const Index m = 2 * n + 1;  // lattice points per axis, spacing 1/(2n)
  CellSoup soup("checkerboard");
  for (Index k = 0; k < m; ++k)
    for (Index j = 0; j < m; ++j)
      for (Index i = 0; i < m; ++i) soup.points.push_back(Vec3(i, j, k) / double(2 * n));
  const auto id = [m](const std::array<Index, 3>& p) { return p[0] + m * (p[1] + m * p[2]); };
  const auto hex = [&](Index x, Index y, Index z, Index s) {
    const std::array<Index, 8> c{
        id({x, y, z}),     id({x + s, y, z}),     id({x + s, y + s, z}),     id({x, y + s, z}),
        id({x, y, z + s}), id({x + s, y, z + s}), id({x + s, y + s, z + s}), id({x, y + s, z + s})};
    soup.add_cell(LinearCell::Hexahedron, c, 1);
  };
  for (Index k = 0; k < n; ++k)
    for (Index j = 0; j < n; ++j)
      for (Index i = 0; i < n; ++i) {
        const Index x = 2 * i, y = 2 * j, z = 2 * k;
        if ((i + j + k) % 2 == 1) {
          for (Index c = 0; c < 8; ++c) hex(x + (c & 1), y + (c >> 1 & 1), z + (c >> 2), 1);
          continue;
        }
        for (int axis = 0; axis < 3; ++axis)
          for (int side = 0; side < 2; ++side) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            for (int a = 0; a < 2; ++a)
              for (int b = 0; b < 2; ++b) {
                std::array<Index, 4> loop;
                const std::array<std::array<int, 2>, 4> uv{
                    {{a, b}, {a + 1, b}, {a + 1, b + 1}, {a, b + 1}}};
                for (int q = 0; q < 4; ++q) {
                  std::array<Index, 3> p{x, y, z};
                  p[axis] += 2 * side;
                  p[u] += uv[q][0];
                  p[v] += uv[q][1];
                  loop[q] = id(p);
                }
                if (side == 0) std::reverse(loop.begin(), loop.end());  // e_u × e_v = e_axis
                soup.add_face(loop);
              }
          }
        soup.end_cell(1);
      }
  PolyMesh mesh = cells_to_poly(std::move(soup));
  drop_unused_points(mesh);  // the centres of the unsplit cubes
  tag_cube_sides(mesh);
  return mesh;
}

// n³ cubes cut by the plane normal·x = offset into pieces: region 1 below, 2 above. Each cube
// face is clipped at shared crossing points, so neighbours split their face alike.
inline PolyMesh plane_cut_grid(Index n, const Vec3& normal, double offset) {
  const HexMesh grid = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {n, n, n});
  CellSoup soup("plane-cut");
  soup.points = grid.points;
  const auto level = [&](Index p) { return normal.dot(grid.points[p]) - offset; };
  std::map<std::pair<Index, Index>, Index> crossing;
  const auto cross = [&](Index a, Index b) {
    const auto key = std::minmax(a, b);
    const auto it = crossing.find(key);
    if (it != crossing.end()) return it->second;
    const double t = level(a) / (level(a) - level(b));
    soup.points.push_back(grid.points[a] + t * (grid.points[b] - grid.points[a]));
    const Index id = static_cast<Index>(soup.points.size()) - 1;
    crossing.emplace(key, id);
    return id;
  };
  for (const auto& h : grid.cells) {
    std::array<std::vector<std::vector<Index>>, 2> pieces;  // faces below / above
    std::vector<Index> cut;
    for (const auto& lf : kHexFaces) {
      std::array<std::vector<Index>, 2> part;
      for (int q = 0; q < 4; ++q) {
        const Index a = h[lf[q]], b = h[lf[(q + 1) % 4]];
        part[level(a) > 0].push_back(a);
        if ((level(a) > 0) != (level(b) > 0)) {
          const Index x = cross(a, b);
          part[0].push_back(x);
          part[1].push_back(x);
          cut.push_back(x);
        }
      }
      for (int s = 0; s < 2; ++s)
        if (part[s].size() >= 3) pieces[s].push_back(part[s]);
    }
    if (cut.empty()) {
      soup.add_cell(LinearCell::Hexahedron, h, level(h[0]) > 0 ? 2 : 1);
      continue;
    }
    std::sort(cut.begin(), cut.end());
    cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
    // The cut polygon counter-clockwise about the normal: outward from the piece below.
    Vec3 centre = Vec3::Zero();
    for (Index p : cut) centre += soup.points[p] / double(cut.size());
    const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.normalized().cross(e1);
    std::sort(cut.begin(), cut.end(), [&](Index a, Index b) {
      const Vec3 da = soup.points[a] - centre, db = soup.points[b] - centre;
      return std::atan2(da.dot(e2), da.dot(e1)) < std::atan2(db.dot(e2), db.dot(e1));
    });
    for (int s = 0; s < 2; ++s) {
      for (const auto& face : pieces[s]) soup.add_face(face);
      std::vector<Index> loop = cut;
      if (s == 1) std::reverse(loop.begin(), loop.end());
      soup.add_face(loop);
      soup.end_cell(s + 1);
    }
  }
  PolyMesh mesh = cells_to_poly(std::move(soup));
  tag_cube_sides(mesh);
  return mesh;
}

// `layers` unit-high prisms stacked along z on a polygonal profile (counter-clockwise).
// Tags: "zmin", "zmax", and "side0" … for the prism walls.
inline PolyMesh prism_stack(const std::vector<Eigen::Vector2d>& profile, int layers) {
  const Index n = static_cast<Index>(profile.size());
  PolyMesh mesh;
  for (int z = 0; z <= layers; ++z)
    for (const auto& p : profile) mesh.points.push_back(Vec3(p.x(), p.y(), z));
  const auto level = [n](int z, Index k) { return z * n + k; };
  const Index zmin = mesh.tag_index("zmin"), zmax = mesh.tag_index("zmax");
  std::vector<Index> sides;
  for (Index k = 0; k < n; ++k) sides.push_back(mesh.tag_index("side" + std::to_string(k)));
  for (int z = 0; z <= layers; ++z) {
    std::vector<Index> loop;  // counter-clockwise seen from above: outward for the cell below
    for (Index k = 0; k < n; ++k) loop.push_back(level(z, k));
    if (z == 0) {
      std::reverse(loop.begin(), loop.end());
      mesh.add_face(loop, 0, kNoIndex, zmin);
    } else {
      mesh.add_face(loop, z - 1, z < layers ? z : kNoIndex, z < layers ? kNoIndex : zmax);
    }
  }
  for (int z = 0; z < layers; ++z)
    for (Index k = 0; k < n; ++k) {
      const Index b = (k + 1) % n;
      const std::array<Index, 4> side{level(z, k), level(z, b), level(z + 1, b), level(z + 1, k)};
      mesh.add_face(side, z, kNoIndex, sides[k]);
    }
  mesh.cell_region.assign(layers, 1);
  return mesh;
}

// Prisms on an L-shaped profile with a long arm: cells whose vertex average lies outside
// them, joined by non-convex L faces whose fan about the vertex average folds.
inline PolyMesh l_prism_stack(int layers) {
  return prism_stack({{0, 0}, {6, 0}, {6, 1}, {1, 1}, {1, 6}, {0, 6}}, layers);
}

// Prisms on a U-shaped profile with long arms: no point sees the tops of both arms, so the
// cells are not star-shaped and the polyhedral space takes them as virtual elements.
inline PolyMesh u_prism_stack(int layers) {
  return prism_stack({{0, 0}, {5, 0}, {5, 5}, {4, 5}, {4, 1}, {1, 1}, {1, 5}, {0, 5}}, layers);
}

// Moves every point along a smooth, non-affine field that vanishes on the cube's sides: the
// cube stays the cube, planar faces inside become warped.
inline void warp(PolyMesh& mesh, double amplitude) {
  constexpr double pi = 3.14159265358979323846;
  for (Vec3& p : mesh.points) {
    const double bubble = std::sin(pi * p.x()) * std::sin(pi * p.y()) * std::sin(pi * p.z());
    p +=
        amplitude * bubble *
        Vec3(std::cos(3.0 * p.y() + 1.0), std::cos(2.0 * p.z() - 0.5), std::sin(4.0 * p.x() + 0.2));
  }
}

}  // namespace volmesh::test
