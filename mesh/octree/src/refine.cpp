// Refinement: the generic predicate fixpoint, the interface criterion, fronts, build_octree.
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_sort.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "volmesh/core/errors.hpp"
#include "volmesh/octree/octree.hpp"

namespace volmesh {

namespace {

// Leaves (by index) whose flag is set, in Morton order.
std::vector<Index> flagged(const std::vector<std::uint8_t>& flags) {
  std::vector<Index> result;
  for (std::size_t i = 0; i < flags.size(); ++i)
    if (flags[i]) result.push_back(static_cast<Index>(i));
  return result;
}

// Batches keep the crossing lists of one batch in memory at a time.
constexpr std::size_t kBatch = std::size_t{1} << 16;

// Regions of grid points, remembered across passes (children share their parent's corners).
class RegionCache {
 public:
  // `tree` is the tree being refined: it changes between fills, only its root matters.
  RegionCache(const Octree& tree, const Domain& domain) : tree_(tree), domain_(domain) {}

  // Queries the points (Morton codes) not seen yet, batched and in parallel.
  void fill(std::vector<std::uint64_t> codes) {
    tbb::parallel_sort(codes.begin(), codes.end());
    codes.erase(std::unique(codes.begin(), codes.end()), codes.end());
    std::vector<std::uint64_t> missing;
    for (const std::uint64_t c : codes)
      if (known_.find(c) == kNoIndex) missing.push_back(c);
    std::vector<Vec3> points(missing.size());
    tbb::parallel_for(std::size_t{0}, missing.size(),
                      [&](std::size_t i) { points[i] = tree_.world(morton_decode(missing[i])); });
    std::vector<Index> regions(missing.size());
    domain_.region(points, regions);
    known_.reserve(known_.size() + missing.size());
    for (std::size_t i = 0; i < missing.size(); ++i) known_.insert(missing[i], regions[i]);
  }
  Index operator()(std::uint64_t code) const { return known_.find(code); }

 private:
  const Octree& tree_;
  const Domain& domain_;
  KeyMap known_;
};

// The two ends of the edge whose midpoint is `mid`: along the one coordinate with the fewest
// trailing zeros (an odd multiple of half the edge), the others being multiples of the edge.
std::pair<GridPoint, GridPoint> edge_from_midpoint(const GridPoint& mid) {
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::countr_zero(mid[a]) < std::countr_zero(mid[axis])) axis = a;
  const std::uint32_t half = std::uint32_t{1} << std::countr_zero(mid[axis]);
  GridPoint lo = mid, hi = mid;
  lo[axis] -= half;
  hi[axis] += half;
  return {lo, hi};
}

// Which of `candidates` (all below the finest level) have corners in different regions or an
// edge crossed by an interface.
std::vector<std::uint8_t> interface_leaves(const Octree& tree, RegionCache& regions,
                                           const Domain& domain,
                                           const std::vector<Index>& candidates) {
  const std::size_t n = candidates.size();
  std::vector<std::uint64_t> corner_codes(8 * n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    const OctreeLeaf& leaf = tree.leaf(candidates[i]);
    for (int k = 0; k < 8; ++k) corner_codes[8 * i + k] = morton_encode(leaf.corner(k));
  });
  regions.fill(corner_codes);

  std::vector<std::uint8_t> selected(n, 0);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    const Index r0 = regions(corner_codes[8 * i]);
    for (int k = 1; k < 8 && !selected[i]; ++k) selected[i] = regions(corner_codes[8 * i + k]) != r0;
  });

  // Uniform corners: the leaf is still cut when an edge is crossed (twice, or touched).
  // An edge is named by its midpoint, unique over all edges of all levels.
  std::vector<std::size_t> uniform;
  for (std::size_t i = 0; i < n; ++i)
    if (!selected[i]) uniform.push_back(i);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges(12 * uniform.size());
  tbb::parallel_for(std::size_t{0}, uniform.size(), [&](std::size_t j) {
    const OctreeLeaf& leaf = tree.leaf(candidates[uniform[j]]);
    for (int e = 0; e < 12; ++e) {
      GridPoint mid = leaf.corner(kEdgeCorners[e][0]);
      mid[e / 4] += leaf.size() / 2;
      edges[12 * j + e] = {morton_encode(mid), static_cast<std::uint32_t>(j)};
    }
  });
  tbb::parallel_sort(edges.begin(), edges.end());
  std::vector<std::size_t> first;  // start of each distinct edge in `edges`
  for (std::size_t k = 0; k < edges.size(); ++k)
    if (k == 0 || edges[k].first != edges[k - 1].first) first.push_back(k);

  std::vector<Vec3> a, b;
  std::vector<std::vector<Crossing>> hits;
  for (std::size_t start = 0; start < first.size(); start += kBatch) {
    const std::size_t end = std::min(first.size(), start + kBatch);
    a.resize(end - start);
    b.resize(end - start);
    tbb::parallel_for(start, end, [&](std::size_t k) {
      const auto [lo, hi] = edge_from_midpoint(morton_decode(edges[first[k]].first));
      a[k - start] = tree.world(lo);
      b[k - start] = tree.world(hi);
    });
    domain.crossings(a, b, hits);
    for (std::size_t k = start; k < end; ++k) {
      if (hits[k - start].empty()) continue;
      const std::size_t stop = k + 1 < first.size() ? first[k + 1] : edges.size();
      for (std::size_t m = first[k]; m < stop; ++m) selected[uniform[edges[m].second]] = 1;
    }
  }
  return selected;
}

void check_level(int level) {
  if (level > kOctreeMaxLevel)
    throw InputError("--level " + std::to_string(level) + " exceeds the maximum " +
                     std::to_string(kOctreeMaxLevel));
  if (level < 0) throw InputError("--level " + std::to_string(level) + " is negative");
}

}  // namespace

int refine(Octree& tree, const LeafPredicate& select, int max_level) {
  check_level(max_level);
  int passes = 0;
  for (;;) {
    std::vector<std::uint8_t> flags(tree.num_leaves(), 0);
    tbb::parallel_for(Index{0}, tree.num_leaves(), [&](Index i) {
      flags[i] = tree.leaf(i).level < max_level && select(tree, i);
    });
    std::vector<Index> chosen = flagged(flags);
    if (chosen.empty()) return passes;
    split_balanced(tree, std::move(chosen));
    ++passes;
  }
}

void refine_toward(Octree& tree, const Domain& domain, int level) {
  check_level(level);
  RegionCache regions(tree, domain);
  // Per leaf: evaluated and not cut. The criterion depends on the leaf alone, so such a
  // leaf is never evaluated again; flags follow the leaves through splits and balancing.
  std::vector<std::uint8_t> uncut(tree.num_leaves(), 0);
  for (;;) {
    std::vector<Index> candidates;
    for (Index i = 0; i < tree.num_leaves(); ++i)
      if (tree.leaf(i).level < level && !uncut[i]) candidates.push_back(i);
    const std::vector<std::uint8_t> selected =
        interface_leaves(tree, regions, domain, candidates);
    std::vector<Index> chosen;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (selected[i])
        chosen.push_back(candidates[i]);
      else
        uncut[candidates[i]] = 1;
    }
    if (chosen.empty()) return;
    // Splitting and balancing only refine, so a surviving leaf keeps its Morton position
    // among the new ones: carry its flag over.
    const std::vector<OctreeLeaf> before(tree.leaves().begin(), tree.leaves().end());
    split_balanced(tree, std::move(chosen));
    std::vector<std::uint8_t> next(tree.num_leaves(), 0);
    std::size_t i = 0;
    for (Index j = 0; j < tree.num_leaves(); ++j) {
      const OctreeLeaf& l = tree.leaf(j);
      const std::uint64_t code = morton_encode(l.anchor);
      while (i < before.size() && morton_encode(before[i].anchor) < code) ++i;
      if (i < before.size() && before[i].anchor == l.anchor && before[i].level == l.level)
        next[j] = uncut[i];
    }
    uncut = std::move(next);
  }
}

RootCube octree_root(const Domain& domain, const OctreeOptions& options) {
  if (options.margin && (!(*options.margin >= 0.0) || !std::isfinite(*options.margin)))
    throw InputError("octree: the margin must be a non-negative number");
  const Box3 box = domain.bounds();
  const Vec3 extent = box.size();
  if (!box.lo.allFinite() || !box.hi.allFinite() || !(extent.minCoeff() >= 0.0) ||
      !(extent.maxCoeff() > 0.0))
    throw InputError("domain: empty or unbounded bounding box; nothing to mesh");
  if (!options.margin && domain.fills_bounds()) return {box.lo, extent.maxCoeff()};
  const double side = extent.maxCoeff() * (1.0 + 2.0 * options.margin.value_or(0.05));
  return {box.centre() - Vec3::Constant(0.5 * side), side};
}

Octree build_octree(const Domain& domain, const OctreeOptions& options) {
  check_level(options.level);
  if (options.level == 0)
    throw InputError("--level 0: the domain is smaller than one cell (the root cube); use a "
                     "level of at least 1");
  for (const BoxFront& f : options.boxes) check_level(f.level);
  for (const SurfaceFront& f : options.surfaces) {
    check_level(f.level);
    if (!f.surface) throw InputError("octree: a surface front without a surface");
  }
  const RootCube root = octree_root(domain, options);
  Octree tree(root.origin, root.side);

  const int base = std::min(options.base_level, options.level);
  refine(tree, [base](const Octree&, Index) { return true; }, std::max(base, 0));
  refine_toward(tree, domain, options.level);
  for (const BoxFront& f : options.boxes) {
    refine(
        tree,
        [&f](const Octree& t, Index i) {
          const OctreeLeaf& leaf = t.leaf(i);
          const Vec3 lo = t.world(leaf.anchor), hi = t.world(leaf.corner(7));
          return (lo.array() < f.box.hi.array()).all() && (hi.array() > f.box.lo.array()).all();
        },
        f.level);
  }
  for (const SurfaceFront& f : options.surfaces) refine_toward(tree, *f.surface, f.level);
  grade(tree, options.cells_between_levels);
  return tree;
}

}  // namespace volmesh
