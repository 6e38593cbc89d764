// CSG expressions as a flat node list, evaluated on the set of primitives containing a point.
#include <utility>

#include "volmesh/domain/analytic_csg.hpp"

namespace volmesh {

Solid::Solid(Primitive p) : primitives_{std::move(p)}, nodes_{{Op::leaf, 0, 0}} {}

Solid Solid::combine(Op op, Solid a, const Solid& b) {
  const int prim_offset = static_cast<int>(a.primitives_.size());
  const int node_offset = static_cast<int>(a.nodes_.size());
  a.primitives_.insert(a.primitives_.end(), b.primitives_.begin(), b.primitives_.end());
  for (Node n : b.nodes_) {
    if (n.op == Op::leaf)
      n.left += prim_offset;
    else
      n.left += node_offset, n.right += node_offset;
    a.nodes_.push_back(n);
  }
  a.nodes_.push_back({op, node_offset - 1, static_cast<int>(a.nodes_.size()) - 1});
  return a;
}

bool Solid::contains(std::uint32_t mask) const {
  std::vector<char> inside(nodes_.size());
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const Node& n = nodes_[k];
    switch (n.op) {
      case Op::leaf: inside[k] = mask >> n.left & 1; break;
      case Op::unite: inside[k] = inside[n.left] || inside[n.right]; break;
      case Op::intersect: inside[k] = inside[n.left] && inside[n.right]; break;
      case Op::subtract: inside[k] = inside[n.left] && !inside[n.right]; break;
    }
  }
  return inside.back();
}

}  // namespace volmesh
