#pragma once
// The projection paper's 2D geometric cache: a uniform grid over the projection plane, each
// cell listing the items whose bounding rectangle meets it, so that finding the triangles
// over a point is a look-up of one cell. Queries take a point's double approximation: the
// rectangles are widened by a relative margin far above its rounding error, so a cell never
// misses an item whose closed rectangle holds the exact point.
#include <array>
#include <span>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::tet::detail {

// xmin, ymin, xmax, ymax
using Rectangle = std::array<double, 4>;

class PlaneCache {
 public:
  explicit PlaneCache(const std::vector<Rectangle>& items);
  // The items whose widened rectangle covers the cell of (x, y), increasing.
  std::span<const Index> near(double x, double y) const;

 private:
  std::array<double, 2> lo_{}, cell_{};
  std::array<Index, 2> cells_{};
  std::vector<Index> begin_, items_;
  Index cell_of(double v, int axis) const;
};

}  // namespace volmesh::tet::detail
