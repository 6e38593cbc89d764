#pragma once
// The leaf-local refinement stages of build_octree on the forest: toward a domain's
// boundaries and interfaces, and into a box. Each decides a leaf from the leaf alone, so it
// is p8est_refine's callback; the balance between rounds is p8est_balance's.
#include "forest.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/octree/key_map.hpp"

namespace volmesh::octree_dist {

// build_octree's interface criterion (refine_toward): a leaf's corners lie in different
// regions of the domain or one of its edges is crossed (or touched) by an interface. The
// regions met are remembered, as eight leaves share a corner; edge verdicts are not: at four
// leaves to an edge they would take most of a rank's memory for few queries saved.
class InterfaceQuery {
 public:
  // `frame`: a tree with the octree's root cube, for world coordinates.
  InterfaceQuery(const Octree& frame, const Domain& domain) : frame_(frame), domain_(domain) {}
  bool on_interface(const OctreeLeaf& leaf);

 private:
  bool corners_differ(const OctreeLeaf& leaf);
  Index region(const GridPoint& p);

  const Octree& frame_;
  const Domain& domain_;
  KeyMap regions_;  // by the point's Morton code
};

// Splits leaves below `level` that the query puts on an interface, keeping the forest
// balanced, until none is; leaves are queried once (their state). Returns the rounds that
// split leaves.
int refine_toward_interfaces(p8est_t* forest, InterfaceQuery& query, int level);

// Splits the leaves below `level` that overlap the box with positive volume, balanced.
int refine_into_box(p8est_t* forest, const Octree& frame, const BoxFront& front);

// Each leaf's state where unknown: cut when its corners lie in different regions (as
// InterfaceQuery::corners_differ). The crossings of the edges, twelve queries of the domain
// per leaf, are left out: a leaf whose edges an interface crosses between corners of one
// region is rare, and for the partition's weights not worth asking every leaf of a uniform
// level about. `frame`: a tree with the octree's root cube. In classify_leaves.cpp.
void classify_leaves(p8est_t* forest, const Octree& frame, const Domain& domain);

}  // namespace volmesh::octree_dist
