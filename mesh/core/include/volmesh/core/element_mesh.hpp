#pragma once
// Meshes with a fixed number of corners per cell (tets, hexes), for FEM assembly and the
// element-based writers (Gmsh, MEDIT, Abaqus). Corner order follows VTK (and Gmsh):
//   tet  (0,1,2) seen from 3 is counter-clockwise, i.e. det(p1-p0, p2-p0, p3-p0) > 0;
//   hex  0-3 the bottom quad counter-clockwise seen from the top, 4-7 above 0-3.
#include <array>
#include <string>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

template <int CellCorners, int FaceCorners>
struct ElementMesh {
  static constexpr int kCellCorners = CellCorners;
  static constexpr int kFaceCorners = FaceCorners;
  std::vector<Vec3> points;
  std::vector<std::array<Index, CellCorners>> cells;
  std::vector<Index> cell_region;  // >= 1
  // Boundary faces, oriented outward, each with a boundary tag.
  std::vector<std::array<Index, FaceCorners>> boundary_faces;
  std::vector<Index> boundary_tag;
  std::vector<std::string> tag_names;

  Index num_points() const { return static_cast<Index>(points.size()); }
  Index num_cells() const { return static_cast<Index>(cells.size()); }
};

using TetMesh = ElementMesh<4, 3>;
using HexMesh = ElementMesh<8, 4>;

// Outward faces of the reference cells in local corner numbers.
inline constexpr std::array<std::array<int, 3>, 4> kTetFaces{
    {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
inline constexpr std::array<std::array<int, 4>, 6> kHexFaces{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

// Edges of the reference cells in local corner numbers, in VTK's order (the order of the
// mid-edge nodes of its quadratic cells): tet 01 12 02 03 13 23; hex bottom loop, top loop,
// verticals.
inline constexpr std::array<std::array<int, 2>, 6> kTetEdges{
    {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}}};
inline constexpr std::array<std::array<int, 2>, 12> kHexEdges{{{0, 1}, {1, 2}, {2, 3}, {3, 0},
                                                               {4, 5}, {5, 6}, {6, 7}, {7, 4},
                                                               {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
// For each tet edge (kTetEdges), the one sharing no corner with it.
inline constexpr std::array<int, 6> kTetOppositeEdges{5, 3, 4, 1, 2, 0};

// Each corner of the reference hex with its three edge neighbours, ordered (as Verdict orders
// them) so that the edges from the corner to them make a positive frame in a valid hex:
// bottom corners (next, previous around the bottom quad, above), top corners (previous, next,
// below). The frame's determinant is 6 times the volume of the corner's tet.
inline constexpr std::array<std::array<int, 4>, 8> kHexCornerFrames{{{0, 1, 3, 4},
                                                                     {1, 2, 0, 5},
                                                                     {2, 3, 1, 6},
                                                                     {3, 0, 2, 7},
                                                                     {4, 7, 5, 0},
                                                                     {5, 4, 6, 1},
                                                                     {6, 5, 7, 2},
                                                                     {7, 6, 4, 3}}};

}  // namespace volmesh
