#pragma once
// A conforming decomposition of any PolyMesh into tetrahedra, for the formats that take
// elements only (Gmsh, MEDIT, Abaqus).
//
// The rule: a tetrahedron stays whole. Every other cell, hexahedra included, is split on
// its cell tessellation (cell_tessellation.hpp): each face into its triangles (a triangle
// whole, a face of four or more vertices fanned about a new point at its vertex average, or
// ear-clipped when that fan would fold), and the cell into one tetrahedron per face
// triangle about a new point at its star centre. A face's split belongs to the face, so both
// of its cells split it alike and the result has no hanging nodes; a hexahedron is split
// like any other cell because the quad it shares with a polyhedron is split about its
// centre. Each tetrahedron keeps its cell's region, each boundary triangle its face's tag.
// The pieces fill each cell exactly as the tessellation does (the face fans are the ones
// core/geometry.hpp measures cell volumes with; ear-clipped faces only differ where warped).
//
// Numbering: the mesh's points keep their indices; then one point per fanned face in face
// order, then one per split cell in cell order. Tetrahedra come cell by cell in cell order.
#include <string>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// Throws InputError naming `source` and the first cell that cannot be split: one with a face
// folded over itself, or one that no point sees whole (not star-shaped about any point),
// e.g. "a.vtu: cell 17 (region 2, 9 faces): no point inside sees all its faces; it cannot be
// split into tetrahedra about one centre". The result passes check_validity.
PolyMesh decompose_into_tets(const PolyMesh& mesh, const std::string& source = "mesh");

}  // namespace volmesh
