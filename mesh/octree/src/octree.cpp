// The leaf table: Morton order, locational-code hash, neighbour queries.
#include "volmesh/octree/octree.hpp"

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "volmesh/core/errors.hpp"

namespace volmesh {

namespace {

bool aligned(const GridPoint& anchor, int level) {
  const std::uint32_t mask = (kOctreeGrid >> level) - 1;
  return ((anchor[0] | anchor[1] | anchor[2]) & mask) == 0;
}

// The other two axes of `axis`, in increasing order.
std::array<int, 2> other_axes(int axis) {
  return axis == 0 ? std::array{1, 2} : axis == 1 ? std::array{0, 2} : std::array{0, 1};
}

}  // namespace

Octree::Octree(const Vec3& origin, double root_size)
    : Octree(origin, root_size, {OctreeLeaf{{0, 0, 0}, 0}}) {}

Octree::Octree(const Vec3& origin, double root_size, std::vector<OctreeLeaf> leaves)
    : origin_(origin), root_size_(root_size), leaves_(std::move(leaves)) {
  if (!(root_size > 0.0) || !std::isfinite(root_size) || !origin.allFinite())
    throw InputError("octree: the root cube must have a finite positive size");
  if (leaves_.size() > static_cast<std::size_t>(kMaxIndex))
    throw InputError("octree: " + std::to_string(leaves_.size()) +
                     " leaves exceed the index limit " + std::to_string(kMaxIndex));
  for (const OctreeLeaf& l : leaves_)
    if (l.level < 0 || l.level > kOctreeMaxLevel || !aligned(l.anchor, l.level) ||
        l.anchor[0] >= kOctreeGrid || l.anchor[1] >= kOctreeGrid || l.anchor[2] >= kOctreeGrid)
      throw InputError("octree: a leaf of level " + std::to_string(l.level) +
                       " is not aligned on its level's grid inside the root");
  std::vector<std::pair<std::uint64_t, OctreeLeaf>> keyed(leaves_.size());
  tbb::parallel_for(std::size_t{0}, leaves_.size(), [&](std::size_t i) {
    keyed[i] = {morton_encode(leaves_[i].anchor), leaves_[i]};
  });
  tbb::parallel_sort(keyed.begin(), keyed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i < keyed.size(); ++i) leaves_[i] = keyed[i].second;
  // Each leaf covers the Morton range [code, code + size^3): they tile the root exactly when
  // the ranges follow each other from 0 to 2^60.
  std::uint64_t next = 0;
  for (const OctreeLeaf& l : leaves_) {
    const std::uint64_t size = l.size();
    if (morton_encode(l.anchor) != next)
      throw InputError("octree: the leaves overlap or leave a gap (they must tile the root)");
    next += size * size * size;
  }
  if (next != std::uint64_t{1} << (3 * kOctreeMaxLevel))
    throw InputError("octree: the leaves do not cover the root");
  leaves_changed();
}

void Octree::leaves_changed() {
  morton_.resize(leaves_.size());
  tbb::parallel_for(std::size_t{0}, leaves_.size(),
                    [&](std::size_t i) { morton_[i] = morton_encode(leaves_[i].anchor); });
  index_buckets();
}

void Octree::index_buckets() {
  int bits = 0;
  while (bits < 3 * kOctreeMaxLevel && (std::size_t{1} << bits) < leaves_.size()) ++bits;
  bucket_shift_ = 3 * kOctreeMaxLevel - bits;
  const std::size_t buckets = std::size_t{1} << bits;
  bucket_first_.assign(buckets + 1, static_cast<Index>(leaves_.size()));
  std::size_t next = 0;  // the first bucket not yet given its first leaf
  for (std::size_t i = 0; i < leaves_.size(); ++i)
    for (const std::size_t b = morton_[i] >> bucket_shift_; next <= b; ++next)
      bucket_first_[next] = static_cast<Index>(i);
}

double Octree::cell_size(int level) const { return std::ldexp(root_size_, -level); }

Vec3 Octree::world(const GridPoint& p) const {
  const double scale = root_size_ / kOctreeGrid;
  return origin_ + scale * Vec3(p[0], p[1], p[2]);
}

int Octree::max_leaf_level() const {
  int level = 0;
  for (const OctreeLeaf& l : leaves_) level = std::max(level, l.level);
  return level;
}

Index Octree::find_leaf(const GridPoint& anchor, int level) const {
  if (level < 0 || level > kOctreeMaxLevel || !aligned(anchor, level) ||
      anchor[0] >= kOctreeGrid || anchor[1] >= kOctreeGrid || anchor[2] >= kOctreeGrid)
    return kNoIndex;
  const Index i = leaf_containing(anchor);
  return leaves_[i].level == level && leaves_[i].anchor == anchor ? i : kNoIndex;
}

Index Octree::leaf_containing(const GridPoint& p) const {
  if (p[0] >= kOctreeGrid || p[1] >= kOctreeGrid || p[2] >= kOctreeGrid) return kNoIndex;
  // Every leaf before the bucket's first starts below p's code, every one from the next
  // bucket's first above it.
  const std::uint64_t code = morton_encode(p);
  const std::size_t b = code >> bucket_shift_;
  const auto first = morton_.begin() + bucket_first_[b], last = morton_.begin() + bucket_first_[b + 1];
  return static_cast<Index>(std::upper_bound(first, last, code) - morton_.begin()) - 1;
}

namespace {

// The neighbour across a face or edge when it is a leaf of the same size anchored at `same`,
// or a coarser leaf containing `same`; false when the neighbours there are finer.
template <class Neighbours>
bool same_or_coarser(const Octree& tree, const GridPoint& same, int level, Neighbours& result) {
  if (const Index d = tree.find_leaf(same, level); d != kNoIndex) {
    result.kind = FaceKind::Same;
    result.leaves[0] = d;
    return true;
  }
  const Index container = tree.leaf_containing(same);
  if (tree.leaf(container).level >= level) return false;
  result.kind = FaceKind::Coarser;
  result.leaves[0] = container;
  return true;
}

}  // namespace

FaceNeighbours Octree::face_neighbours(Index leaf, int face) const {
  const OctreeLeaf& c = leaves_[leaf];
  const int axis = face / 2;
  const bool high = face & 1;
  const std::uint32_t s = c.size();
  FaceNeighbours result;
  if (high ? c.anchor[axis] + s == kOctreeGrid : c.anchor[axis] == 0) return result;

  GridPoint same = c.anchor;
  same[axis] = high ? c.anchor[axis] + s : c.anchor[axis] - s;
  if (same_or_coarser(*this, same, c.level, result)) return result;
  // Finer: the leaf touching each quarter of the face at the quarter's low corner.
  result.kind = FaceKind::Finer;
  const auto [u, v] = other_axes(axis);
  const std::uint32_t half = s / 2;
  for (int q = 0; q < 4; ++q) {
    GridPoint p = same;
    p[axis] = high ? c.anchor[axis] + s : c.anchor[axis] - half;
    p[u] += (q & 1) * half;
    p[v] += (q >> 1) * half;
    Index d = find_leaf(p, c.level + 1);
    if (d == kNoIndex) {
      if (!high) p[axis] = c.anchor[axis] - 1;
      d = leaf_containing(p);
    }
    result.leaves[q] = d;
  }
  return result;
}

EdgeNeighbours Octree::edge_neighbours(Index leaf, int edge) const {
  const OctreeLeaf& c = leaves_[leaf];
  const int axis = edge / 4;
  const auto [u, v] = other_axes(axis);
  const bool high_u = edge & 1, high_v = edge >> 1 & 1;
  const std::uint32_t s = c.size();
  EdgeNeighbours result;
  if (high_u ? c.anchor[u] + s == kOctreeGrid : c.anchor[u] == 0) return result;
  if (high_v ? c.anchor[v] + s == kOctreeGrid : c.anchor[v] == 0) return result;

  GridPoint same = c.anchor;
  same[u] = high_u ? c.anchor[u] + s : c.anchor[u] - s;
  same[v] = high_v ? c.anchor[v] + s : c.anchor[v] - s;
  if (same_or_coarser(*this, same, c.level, result)) return result;
  result.kind = FaceKind::Finer;
  const std::uint32_t half = s / 2;
  for (int k = 0; k < 2; ++k) {
    GridPoint p = same;
    p[axis] += k * half;
    p[u] = high_u ? c.anchor[u] + s : c.anchor[u] - half;
    p[v] = high_v ? c.anchor[v] + s : c.anchor[v] - half;
    Index d = find_leaf(p, c.level + 1);
    if (d == kNoIndex) {
      if (!high_u) p[u] = c.anchor[u] - 1;
      if (!high_v) p[v] = c.anchor[v] - 1;
      d = leaf_containing(p);
    }
    result.leaves[k] = d;
  }
  return result;
}

void Octree::split(std::span<const Index> which) {
  if (which.empty()) return;
  std::vector<std::uint8_t> split_leaf(leaves_.size(), 0);
  for (const Index i : which) {
    if (leaves_[i].level >= kOctreeMaxLevel)
      throw InputError("octree: cannot split a leaf of the maximum level " +
                       std::to_string(kOctreeMaxLevel));
    split_leaf[i] = 1;
  }
  std::size_t count = leaves_.size();
  for (const std::uint8_t f : split_leaf) count += 7 * f;
  if (count > static_cast<std::size_t>(kMaxIndex))
    throw InputError("octree: refining to " + std::to_string(count) +
                     " leaves exceeds the index limit " + std::to_string(kMaxIndex) +
                     "; lower the level");
  // Children occupy their parent's Morton range in child order (x bit lowest), so emitting
  // them in place keeps the Morton order.
  // Child k's Morton code is its parent's plus k interleaved at the child's size.
  std::vector<OctreeLeaf> next;
  std::vector<std::uint64_t> codes;
  next.reserve(count);
  codes.reserve(count);
  for (std::size_t i = 0; i < leaves_.size(); ++i) {
    const OctreeLeaf& c = leaves_[i];
    if (!split_leaf[i]) {
      next.push_back(c);
      codes.push_back(morton_[i]);
      continue;
    }
    const std::uint32_t half = c.size() / 2;
    const int shift = 3 * (kOctreeMaxLevel - c.level - 1);
    for (int k = 0; k < 8; ++k) {
      next.push_back({{c.anchor[0] + (k & 1) * half, c.anchor[1] + (k >> 1 & 1) * half,
                       c.anchor[2] + (k >> 2 & 1) * half},
                      c.level + 1});
      codes.push_back(morton_[i] + (std::uint64_t(k) << shift));
    }
  }
  leaves_ = std::move(next);
  morton_ = std::move(codes);
  index_buckets();
}

}  // namespace volmesh
