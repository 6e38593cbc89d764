#pragma once
// The front's local target size h(x): from the boundary triangles near the boundary, growing
// inward at a bounded rate to the target size (docs/methods.md, "tet-front", grading).
//
// Each boundary point p carries e(p): the mean length of its incident edges where that is
// below half the target size, else the target size (a boundary made for a size, its edges
// mostly 0.5 to 1 times it, fits it: its mesh is the uniform one); then
//     h(x) = min(cap, min over boundary points p of e(p) + rate |x - p|),
// the largest function with gradient at most `rate` that stays below e at the boundary and
// below cap everywhere. cap is the target size (--size), or the interior size when given
// (--interior-size), so that the size keeps growing past --size deeper inside. Neighbouring
// tets, about h(x) apart, then differ in size by a factor of about 1 + rate.
#include <array>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::tet::front {

// The size's growth per unit distance from the boundary.
inline constexpr double kGradingRate = 0.25;
// A boundary point fits the target size when its mean edge is at least the size over this.
inline constexpr double kFitRatio = 2.0;

class SizeField {
 public:
  // points and triangles: every surface's, boundary points unused by any triangle ignored.
  SizeField(const std::vector<Vec3>& points, const std::vector<std::array<Index, 3>>& triangles,
            double size, double interior_size);

  double at(const Vec3& x) const;
  // A lower bound of h over the box [lo, hi].
  double min_in_box(const Vec3& lo, const Vec3& hi) const;
  double min() const { return min_; }
  double cap() const { return cap_; }
  // The field's gradient bound: 0 when it is the constant cap (a boundary no finer than it).
  double rate() const { return uniform() ? 0.0 : kGradingRate; }
  bool uniform() const { return min_ >= cap_; }
  // The largest size at a point within reach · h(that point) of a point of size h: a face
  // whose reach of `reach` times its own size covers x has a size at most this.
  double largest_reaching(double h, double reach) const;

 private:
  struct Node {
    Vec3 lo, hi;
    int child = -1;             // its 8 children's entry in child_index_, or -1 for a leaf
    int first = 0, count = 0;   // a leaf's candidates in candidates_
  };
  int build(const Vec3& lo, const Vec3& hi, std::vector<Index> candidates, int depth);

  std::vector<Vec3> seeds_;    // boundary points
  std::vector<double> value_;  // e(p), capped
  double cap_ = 0.0, min_ = 0.0;
  std::vector<Node> nodes_;  // the tree of candidates, its root first
  std::vector<int> child_index_;
  std::vector<Index> candidates_;
};

}  // namespace volmesh::tet::front
