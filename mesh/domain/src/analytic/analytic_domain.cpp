// The analytic domain: validation, bounds and region list at construction; point queries.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "analytic_shapes.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh {
namespace {

using Mask = AnalyticDomain::Mask;

Box3 intersect(const Box3& a, const Box3& b) { return {a.lo.cwiseMax(b.lo), a.hi.cwiseMin(b.hi)}; }

// Union over the labelled bitmasks of the box around the primitives each requires.
Box3 labelled_bounds(const std::vector<Box3>& boxes, const std::vector<Index>& table) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Box3 all{Vec3::Constant(kInf), Vec3::Constant(-kInf)};
  for (Mask m = 1; m < table.size(); ++m) {
    if (table[m] == 0) continue;
    Box3 b{Vec3::Constant(-kInf), Vec3::Constant(kInf)};
    for (std::size_t i = 0; i < boxes.size(); ++i)
      if (m >> i & 1) b = intersect(b, boxes[i]);
    if ((b.lo.array() > b.hi.array()).any()) continue;
    if (!b.lo.allFinite() || !b.hi.allFinite())
      throw InputError("analytic domain: region " + std::to_string(table[m]) +
                       " is unbounded (inside only unbounded primitives)");
    all = {all.lo.cwiseMin(b.lo), all.hi.cwiseMax(b.hi)};
  }
  if ((all.lo.array() > all.hi.array()).any())
    throw InputError("analytic domain: no region can contain any point");
  return all;
}

// Labels met by a grid of lines along each axis through the box, sorted (crossings are
// exact, so a region is found as soon as one line passes through it).
std::vector<Index> labels_on_lines(const Domain& d, const Box3& box) {
  constexpr int kLines = 32;
  // The lines start and end this fraction of the box outside it (and a little more for a
  // flat box), so that every one begins and ends in region 0.
  constexpr double kMargin = 1e-3;
  constexpr double kFlatMargin = 1e-12;
  const Vec3 margin = kMargin * box.size() + Vec3::Constant(kFlatMargin);
  const Vec3 lo = box.lo - margin, size = box.size() + 2.0 * margin;
  std::vector<Index> seen;
  for (int axis = 0; axis < 3; ++axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    for (int p = 0; p < kLines; ++p)
      for (int q = 0; q < kLines; ++q) {
        Vec3 a = lo;
        a[i] += (p + 0.5) / kLines * size[i];
        a[j] += (q + 0.5) / kLines * size[j];
        Vec3 b = a;
        b[axis] += size[axis];
        seen.push_back(d.region(a));
        for (const Crossing& c : d.crossings(a, b)) seen.insert(seen.end(), {c.before, c.after});
      }
  }
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  return seen;
}

}  // namespace

AnalyticDomain::AnalyticDomain(std::vector<Primitive> primitives, std::vector<Index> table)
    : primitives_(std::move(primitives)), table_(std::move(table)) {
  const std::size_t n = primitives_.size();
  if (n == 0 || n > kMaxPrimitives)
    throw InputError("analytic domain: needs 1 to " + std::to_string(kMaxPrimitives) +
                     " primitives, got " + std::to_string(n));
  if (table_.size() != std::size_t{1} << n)
    throw InputError("analytic domain: region table has " + std::to_string(table_.size()) +
                     " entries, expected 2^" + std::to_string(n));
  if (table_[0] != 0)
    throw InputError("analytic domain: region " + std::to_string(table_[0]) +
                     " contains everything outside the primitives (unbounded)");
  if (*std::min_element(table_.begin(), table_.end()) < 0)
    throw InputError("analytic domain: region labels must be >= 0");
  for (std::size_t i = 0; i < n; ++i) analytic::validate(primitives_[i], static_cast<int>(i));
  std::vector<Box3> boxes;
  for (const Primitive& p : primitives_) {
    boxes.push_back(analytic::world_bounds(p));
    // A point outside the grown box is certainly outside the primitive: most queries
    // skip the exact test, and rounding in the box never changes an answer (the growth,
    // relative to the box's size and position, is far above the rounding of its corners).
    constexpr double kGrowth = 1e-9;
    const Box3& b = boxes.back();
    const Vec3 pad = kGrowth * (b.size() + b.lo.cwiseAbs() + b.hi.cwiseAbs());
    reach_.push_back({b.lo - pad, b.hi + pad});
  }
  bounds_ = labelled_bounds(boxes, table_);
  // Until the scan has found which labels occur, points on surfaces count as outside
  // them (winner() falls back to that), so that no label is seen that only a face has.
  occurs_.assign(table_.size(), 0);
  for (Index r : labels_on_lines(*this, bounds_))
    if (r != 0) regions_.push_back(r);
  for (std::size_t m = 0; m < table_.size(); ++m)
    occurs_[m] = table_[m] == 0 || std::binary_search(regions_.begin(), regions_.end(), table_[m]);
}

AnalyticDomain::Masks AnalyticDomain::classify(const Vec3& p) const {
  Masks m;
  for (std::size_t i = 0; i < primitives_.size(); ++i) {
    if (analytic::apart(reach_[i], p)) continue;
    const analytic::Side s = analytic::classify(primitives_[i], p);
    if (s == analytic::Side::in) m.in |= Mask{1} << i;
    if (s == analytic::Side::on) m.on |= Mask{1} << i;
  }
  return m;
}

Index AnalyticDomain::region(const Vec3& p) const { return table_[winner(classify(p), p)]; }

AnalyticDomain::Nearest AnalyticDomain::nearest_interface(const Vec3& p) const {
  const Mask w = winner(classify(p), p);
  int best = 0;
  bool best_separates = false;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < primitives_.size(); ++i) {
    const Mask bit = Mask{1} << i;
    // Surfaces that separate two regions here come first; then the nearest.
    const bool separates = table_[w | bit] != table_[w & ~bit];
    const double d = std::abs(analytic::distance(
        primitives_[i].shape, analytic::to_local(primitives_[i].frame, p)));
    if (separates > best_separates || (separates == best_separates && d < best_distance)) {
      best = static_cast<int>(i);
      best_separates = separates;
      best_distance = d;
    }
  }
  const Primitive& prim = primitives_[best];
  const Mask bit = Mask{1} << best;
  Vec3 n = prim.frame.rotation *
           analytic::gradient(prim.shape, analytic::to_local(prim.frame, p));
  if (table_[w & ~bit] > table_[w | bit]) n = -n;  // the outside of this primitive wins
  return {best, n};
}

Vec3 AnalyticDomain::normal(const Vec3& p) const { return nearest_interface(p).normal; }

std::string AnalyticDomain::surface_name(const Vec3& p) const {
  return primitives_[nearest_interface(p).primitive].name;
}

AnalyticDomain multi_material_domain(std::vector<Primitive> primitives) {
  const std::size_t n = primitives.size();
  // Too many primitives: an empty table, for the constructor to report.
  std::vector<Index> table(n <= AnalyticDomain::kMaxPrimitives ? std::size_t{1} << n : 0);
  for (std::size_t m = 0; m < table.size(); ++m) table[m] = static_cast<Index>(m);
  return AnalyticDomain(std::move(primitives), std::move(table));
}

}  // namespace volmesh
