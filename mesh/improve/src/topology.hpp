#pragma once
// The topological changes (Stellar's family 2). Each replaces a few tets by others over the
// same region, only when the smallest quality rises and every new tet is positive by the
// exact test; none changes a fixed face.
#include "tet_complex.hpp"

namespace volmesh::improve {

// Edge removal: the ring of tets around edge ab (3 to kMaxRing of them, none holding a fixed
// face) replaced by the best triangulation of its link polygon coned to a and b (Klincsek's
// dynamic programme). Returns the ring's size, 0 when nothing changed.
inline constexpr int kMaxRing = 7;
int remove_edge(TetComplex& mesh, Index a, Index b);

// Multi-face removal: the faces sandwiched between the apexes a and b of tet t's face `face`
// and of the tet across it, grown from that face, replaced by the edge ab (2m tets by m + 2;
// m = 1 is the 2-3 flip). Returns the number of faces removed, 0 when nothing changed.
int remove_faces(TetComplex& mesh, Index t, int face);

// Edge contraction: the free point `gone` merges into `kept`, which stays where it is or,
// when free too, moves to the edge's midpoint if that is better.
bool contract_edge(TetComplex& mesh, Index gone, Index kept);

}  // namespace volmesh::improve
