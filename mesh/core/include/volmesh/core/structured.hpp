#pragma once
// Structured meshes of an axis-aligned box: the reference meshes of the element tests and
// of `volmesh mesh grid`.
#include <array>

#include "volmesh/core/element_mesh.hpp"

namespace volmesh {

// n[0]×n[1]×n[2] hexes; boundary quads tagged "xmin", "xmax", "ymin", "ymax", "zmin", "zmax";
// region 1.
HexMesh structured_hex_mesh(const Vec3& lo, const Vec3& hi, const std::array<Index, 3>& n);

// Each hex of structured_hex_mesh split into the 6 Kuhn tets around its main diagonal; the
// split is the same in every cell, so the tet mesh is conforming.
TetMesh kuhn_tet_mesh(const Vec3& lo, const Vec3& hi, const std::array<Index, 3>& n);

}  // namespace volmesh
