#include "plane_cache.hpp"

#include <algorithm>
#include <cmath>

namespace volmesh::tet::detail {

namespace {
// How far rectangles are widened, relative to the extent of them all.
constexpr double kMargin = 1e-9;
// Items per cell the grid aims at, on average.
constexpr double kItemsPerCell = 2.0;
}  // namespace

PlaneCache::PlaneCache(const std::vector<Rectangle>& rectangles) {
  if (rectangles.empty()) {
    cells_ = {1, 1};
    cell_ = {1.0, 1.0};
    begin_ = {0, 0};
    return;
  }
  std::array<double, 2> hi{};
  lo_ = {INFINITY, INFINITY};
  hi = {-INFINITY, -INFINITY};
  for (const Rectangle& r : rectangles)
    for (int a = 0; a < 2; ++a) {
      lo_[a] = std::min(lo_[a], r[a]);
      hi[a] = std::max(hi[a], r[2 + a]);
    }
  const double extent = std::max({hi[0] - lo_[0], hi[1] - lo_[1], 1e-300});
  const double margin = kMargin * extent;
  for (int a = 0; a < 2; ++a) {
    lo_[a] -= 2.0 * margin;
    hi[a] += 2.0 * margin;
  }
  // Square cells, about kItemsPerCell items each.
  const double area = (hi[0] - lo_[0]) * (hi[1] - lo_[1]);
  const double wanted = std::max(1.0, static_cast<double>(rectangles.size()) / kItemsPerCell);
  const double side = std::max(std::sqrt(area / wanted), extent * 1e-6);
  for (int a = 0; a < 2; ++a) {
    cells_[a] = static_cast<Index>(std::clamp(std::ceil((hi[a] - lo_[a]) / side), 1.0, 4096.0));
    cell_[a] = (hi[a] - lo_[a]) / cells_[a];
  }
  const auto span = [&](const Rectangle& r) {
    return std::array<Index, 4>{cell_of(r[0] - margin, 0), cell_of(r[1] - margin, 1),
                                cell_of(r[2] + margin, 0), cell_of(r[3] + margin, 1)};
  };
  begin_.assign(static_cast<std::size_t>(cells_[0]) * cells_[1] + 1, 0);
  for (const Rectangle& r : rectangles) {
    const auto s = span(r);
    for (Index j = s[1]; j <= s[3]; ++j)
      for (Index i = s[0]; i <= s[2]; ++i) ++begin_[j * cells_[0] + i + 1];
  }
  for (std::size_t c = 1; c < begin_.size(); ++c) begin_[c] += begin_[c - 1];
  items_.resize(static_cast<std::size_t>(begin_.back()));
  std::vector<Index> next(begin_.begin(), begin_.end() - 1);
  for (Index k = 0; k < static_cast<Index>(rectangles.size()); ++k) {
    const auto s = span(rectangles[k]);
    for (Index j = s[1]; j <= s[3]; ++j)
      for (Index i = s[0]; i <= s[2]; ++i) items_[next[j * cells_[0] + i]++] = k;
  }
}

Index PlaneCache::cell_of(double v, int axis) const {
  const double c = std::floor((v - lo_[axis]) / cell_[axis]);
  return static_cast<Index>(std::clamp(c, 0.0, static_cast<double>(cells_[axis] - 1)));
}

std::span<const Index> PlaneCache::near(double x, double y) const {
  const Index c = cell_of(y, 1) * cells_[0] + cell_of(x, 0);
  return {items_.data() + begin_[c], items_.data() + begin_[c + 1]};
}

}  // namespace volmesh::tet::detail
