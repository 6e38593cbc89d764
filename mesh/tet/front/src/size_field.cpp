#include "size_field.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace volmesh::tet::front {

namespace {

// The tree of candidates splits a box while it keeps more boundary points than this.
constexpr std::size_t kLeafCandidates = 8;
// and is wider than this fraction of the least size in it (deep inside, the nearest few
// boundary points tie to within less than a box: many remain candidates in any small box),
constexpr double kLeafSizeFraction = 0.5;
// and no deeper than this (boxes 2^-14 of the boundary's).
constexpr int kMaxDepth = 14;

double min_distance(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return (p - p.cwiseMax(lo).cwiseMin(hi)).norm();
}

double max_distance(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return (p - lo).cwiseAbs().cwiseMax((p - hi).cwiseAbs()).norm();
}

int child_of(const Vec3& x, const Vec3& mid) {
  return (x.x() >= mid.x() ? 1 : 0) | (x.y() >= mid.y() ? 2 : 0) | (x.z() >= mid.z() ? 4 : 0);
}

}  // namespace

SizeField::SizeField(const std::vector<Vec3>& points,
                     const std::vector<std::array<Index, 3>>& triangles, double size,
                     double interior_size)
    : cap_(std::max(size, interior_size)) {
  // Each edge once per triangle: an interior edge of a closed surface is counted from both
  // sides, so every incident edge weighs the same.
  std::vector<double> sum(points.size(), 0.0);
  std::vector<int> count(points.size(), 0);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      const double length = (points[a] - points[b]).norm();
      sum[a] += length;
      sum[b] += length;
      count[a] += 1;
      count[b] += 1;
    }
  min_ = cap_;
  std::vector<Index> all;
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (count[p] == 0) continue;
    all.push_back(static_cast<Index>(seeds_.size()));
    seeds_.push_back(points[p]);
    const double mean = sum[p] / count[p];
    value_.push_back(mean * kFitRatio >= size ? size : mean);
    min_ = std::min(min_, value_.back());
  }
  if (uniform() || seeds_.empty()) return;
  Vec3 lo = seeds_.front(), hi = lo;
  for (const Vec3& p : seeds_) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  build(lo, hi, std::move(all), 0);
}

int SizeField::build(const Vec3& lo, const Vec3& hi, std::vector<Index> candidates, int depth) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back({lo, hi});
  // The least upper bound of h over the box, then the points that may reach below it.
  double upper = cap_;
  for (const Index v : candidates)
    upper = std::min(upper, value_[v] + kGradingRate * max_distance(seeds_[v], lo, hi));
  double least = upper;
  std::erase_if(candidates, [&](Index v) {
    const double lower = value_[v] + kGradingRate * min_distance(seeds_[v], lo, hi);
    least = std::min(least, lower);
    return lower >= cap_ || lower > upper;
  });
  if (candidates.size() <= kLeafCandidates || depth >= kMaxDepth ||
      (hi - lo).norm() <= kLeafSizeFraction * least) {
    nodes_[id].first = static_cast<int>(candidates_.size());
    nodes_[id].count = static_cast<int>(candidates.size());
    candidates_.insert(candidates_.end(), candidates.begin(), candidates.end());
    return id;
  }
  const Vec3 mid = 0.5 * (lo + hi);
  std::array<int, 8> children{};
  for (int c = 0; c < 8; ++c) {
    Vec3 clo, chi;
    for (int a = 0; a < 3; ++a) {
      const bool upper_half = (c >> a) & 1;
      clo[a] = upper_half ? mid[a] : lo[a];
      chi[a] = upper_half ? hi[a] : mid[a];
    }
    children[c] = build(clo, chi, candidates, depth + 1);
  }
  // Each child's subtree lies between it and its next sibling: the 8 are found by a table.
  nodes_[id].child = static_cast<int>(child_index_.size());
  child_index_.insert(child_index_.end(), children.begin(), children.end());
  return id;
}

double SizeField::at(const Vec3& x) const {
  if (uniform() || nodes_.empty()) return cap_;
  const Node* n = &nodes_.front();
  const bool inside = (x.array() >= n->lo.array()).all() && (x.array() <= n->hi.array()).all();
  double h = cap_;
  if (!inside) {
    // Outside the boundary's box (no region point is): every boundary point counts.
    for (std::size_t v = 0; v < seeds_.size(); ++v)
      h = std::min(h, value_[v] + kGradingRate * (x - seeds_[v]).norm());
    return h;
  }
  while (n->child >= 0) n = &nodes_[child_index_[n->child + child_of(x, 0.5 * (n->lo + n->hi))]];
  for (int k = 0; k < n->count; ++k) {
    const Index v = candidates_[n->first + k];
    h = std::min(h, value_[v] + kGradingRate * (x - seeds_[v]).norm());
  }
  return h;
}

double SizeField::min_in_box(const Vec3& lo, const Vec3& hi) const {
  if (uniform()) return cap_;
  return std::max(min_, at(0.5 * (lo + hi)) - kGradingRate * 0.5 * (hi - lo).norm());
}

double SizeField::largest_reaching(double h, double reach) const {
  const double shrink = 1.0 - rate() * reach;
  return shrink > 0.0 ? std::min(cap_, h / shrink) : cap_;
}

}  // namespace volmesh::tet::front
