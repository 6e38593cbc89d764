#include "refine_stages.hpp"

namespace volmesh::octree_dist {

Index InterfaceQuery::region(const GridPoint& p) {
  const std::uint64_t code = morton_encode(p);
  Index r = regions_.find(code);
  if (r == kNoIndex) {
    r = domain_.region(frame_.world(p));
    regions_.insert(code, r);
  }
  return r;
}

bool InterfaceQuery::corners_differ(const OctreeLeaf& leaf) {
  const Index first = region(leaf.corner(0));
  for (int k = 1; k < 8; ++k)
    if (region(leaf.corner(k)) != first) return true;
  return false;
}

bool InterfaceQuery::on_interface(const OctreeLeaf& leaf) {
  if (corners_differ(leaf)) return true;
  for (const auto& [a, b] : kEdgeCorners)
    if (!domain_.crossings(frame_.world(leaf.corner(a)), frame_.world(leaf.corner(b))).empty()) return true;
  return false;
}

namespace {

struct InterfaceStage {
  InterfaceQuery& query;
  int level;
};

int split_on_interface(p8est_t* forest, p4est_topidx_t, p8est_quadrant_t* q) {
  auto& stage = *static_cast<InterfaceStage*>(forest->user_pointer);
  if (q->level >= stage.level) return 0;
  LeafData& d = leaf_data(*q);
  if (d.state == LeafState::unknown)
    d.state = stage.query.on_interface(to_leaf(*q)) ? LeafState::cut : LeafState::uncut;
  return d.state == LeafState::cut;
}

struct BoxStage {
  const Octree& frame;
  const BoxFront& front;
};

// As build_octree's box front: the leaf's open box meets the front's.
int split_in_box(p8est_t* forest, p4est_topidx_t, p8est_quadrant_t* q) {
  const auto& stage = *static_cast<const BoxStage*>(forest->user_pointer);
  if (q->level >= stage.front.level) return 0;
  const OctreeLeaf leaf = to_leaf(*q);
  const Vec3 lo = stage.frame.world(leaf.anchor), hi = stage.frame.world(leaf.corner(7));
  return (lo.array() < stage.front.box.hi.array()).all() && (hi.array() > stage.front.box.lo.array()).all();
}

}  // namespace

int refine_toward_interfaces(p8est_t* forest, InterfaceQuery& query, int level) {
  InterfaceStage stage{query, level};
  return refine_until_stable(forest, split_on_interface, &stage);
}

int refine_into_box(p8est_t* forest, const Octree& frame, const BoxFront& front) {
  BoxStage stage{frame, front};
  return refine_until_stable(forest, split_in_box, &stage);
}

}  // namespace volmesh::octree_dist
