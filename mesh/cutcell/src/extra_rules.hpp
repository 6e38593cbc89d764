#pragma once
// The first two of the paper's extra refinement rules, decided in one place for the grid
// passes (grid_rules.cpp) and for the rounds between them (local_rules.cpp), which differ
// only in where they find what the rules look at: a grid's tables, or the tree and the
// domain. A rule selects a cut leaf below the deepest level of the rules when
//  - an edge of the leaf is crossed more than once (the paper's rule, which also covers an
//    edge of a larger leaf whose midpoint lies in another region), or
//  - an interface passes within clearance * size of the centre of one of its transition
//    faces, along the leaf's edge direction into the leaf: no edge of the leaf runs there,
//    so the vertex moves do not see it and the piece between would be a sliver. Split, the
//    centre becomes a corner of edges that the moves clear.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "volmesh/domain/domain.hpp"

namespace volmesh::cutcell {

// The transversal crossings among hits (tangential touches left out), capped at 255 as a
// grid keeps them per edge.
std::uint8_t transversal_crossings(const std::vector<Crossing>& hits);

// What the rules look at in the leaves they test (cut, below the deepest level).
struct RuleCandidates {
  std::vector<Index> leaves;
  // Per leaf: the crossings along its most crossed edge, that edge's fine edges' summed
  // (the whole edge, or its two halves beside a midpoint vertex).
  std::vector<int> most_crossed;
  // Per transition face of a leaf: the segment from the face's centre one leaf edge into
  // the leaf; segment_leaf indexes `leaves`.
  std::vector<std::size_t> segment_leaf;
  std::vector<Vec3> from, to;

  void add_leaf(Index leaf, int most_crossed_edge);
  // A transition face of the last leaf added: face k (axis k / 2, side k % 2), its centre,
  // the leaf's edge `size`.
  void add_transition_face(int face, const Vec3& centre, double size);
};

// The leaves a rule selects, in the candidates' order. clearance 0: the first rule alone.
std::vector<Index> leaves_selected(const RuleCandidates& candidates, const Domain& domain, double clearance);

}  // namespace volmesh::cutcell
