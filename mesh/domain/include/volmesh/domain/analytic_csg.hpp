#pragma once
// Constructive solid geometry over analytic primitives: union (|), intersection (&) and
// difference (-) of closed solids, compiled into the region table of an AnalyticDomain.
#include <cstdint>
#include <utility>
#include <vector>

#include "volmesh/domain/analytic.hpp"

namespace volmesh {

class Solid {
 public:
  Solid(Primitive p);  // implicit: a primitive is a solid

  friend Solid operator|(Solid a, const Solid& b) { return combine(Op::unite, std::move(a), b); }
  friend Solid operator&(Solid a, const Solid& b) { return combine(Op::intersect, std::move(a), b); }
  friend Solid operator-(Solid a, const Solid& b) { return combine(Op::subtract, std::move(a), b); }

  // The primitives of every operand, in order (a primitive used twice appears twice).
  const std::vector<Primitive>& primitives() const { return primitives_; }
  // Whether a point inside exactly the primitives of `mask` (bit i for primitives()[i])
  // is inside the solid.
  bool contains(std::uint32_t mask) const;

 private:
  enum class Op : std::uint8_t { leaf, unite, intersect, subtract };
  struct Node {
    Op op;
    int left, right;  // operand nodes; for a leaf, left is the primitive index
  };
  static Solid combine(Op op, Solid a, const Solid& b);

  std::vector<Primitive> primitives_;
  std::vector<Node> nodes_;  // operands before the nodes using them; the root is last
};

// One region, label 1, inside the solid.
AnalyticDomain solid_domain(const Solid& solid);

// Labelled solids; where they overlap, the later one wins (list an inclusion after the
// matrix it sits in). Labels must be >= 1.
struct Layer {
  Solid solid;
  Index label;
};
AnalyticDomain layered_domain(const std::vector<Layer>& layers);

}  // namespace volmesh
