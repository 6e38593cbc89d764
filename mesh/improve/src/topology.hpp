#pragma once
// The topological changes (Stellar's family 2). Each replaces a few tets by others over the
// same region, only when the smallest quality rises and every new tet is positive by the
// exact test; none changes a fixed face.
#include <optional>

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

// Coarsening's contraction, `kept` staying where it is: `gone` free, or sliding and `kept` in
// the closure of its triangle or edge. The smallest quality of the new tets when every one is
// positive by the exact test, the link condition holds (the boundary coned to a point at
// infinity, so no inner edge between boundary points goes) and no boundary face folds over;
// nullopt otherwise.
std::optional<double> contraction_quality(const TetComplex& mesh, Index gone, Index kept);
// Whether `gone` may merge into `kept` (at the same place: the caller's to check): they share
// an edge and the link condition holds.
bool merge_allowed(const TetComplex& mesh, Index gone, Index kept);
// Carries out a contraction contraction_quality() allowed.
void contract(TetComplex& mesh, Index gone, Index kept);

}  // namespace volmesh::improve
