// The vertex table of a tree updated from the table it had before some leaves were split:
// a split removes no vertex, so the known codes are merged with the corners of the new
// leaves, and only vertices around the new leaves are classified again. The refinement
// passes of the cut cells rebuild the table after each split, a few leaves at a time:
// sorting every leaf's corners each time would cost more than the splits.
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_sort.h>

#include <algorithm>

#include "vertex_table.hpp"

namespace volmesh {
namespace {

std::uint32_t known_size(const OctreeVertices& known, std::size_t leaf) {
  const auto& c = known.leaf_corners[leaf];
  return known.coords[c[7]][0] - known.coords[c[0]][0];
}

Index index_of(const std::vector<std::uint64_t>& codes, std::uint64_t code) {
  return static_cast<Index>(std::lower_bound(codes.begin(), codes.end(), code) - codes.begin());
}

}  // namespace

OctreeVertices refined_vertex_geometry(const Octree& tree, const OctreeVertices& known,
                                       std::vector<Index>& fresh) {
  const std::size_t n = tree.leaves().size(), m = known.leaf_corners.size();
  // The known leaf each leaf is (same anchor and size), kNoIndex for the new ones; both
  // lists are in Morton order and a split leaf's first child shares its anchor.
  std::vector<Index> same(n, kNoIndex);
  std::vector<std::size_t> added;
  for (std::size_t j = 0, i = 0; j < n; ++j) {
    const OctreeLeaf& l = tree.leaf(j);
    const std::uint64_t code = morton_encode(l.anchor);
    while (i < m && known.codes[known.leaf_corners[i][0]] < code) ++i;
    if (i < m && known.codes[known.leaf_corners[i][0]] == code && known_size(known, i) == l.size())
      same[j] = static_cast<Index>(i);
    else
      added.push_back(j);
  }
  // The new leaves' corners, and those of them that are new vertices.
  std::vector<std::uint64_t> added_corners(8 * added.size());
  tbb::parallel_for(std::size_t{0}, added.size(), [&](std::size_t k) {
    for (int c = 0; c < 8; ++c) added_corners[8 * k + c] = morton_encode(tree.leaf(added[k]).corner(c));
  });
  std::vector<std::uint64_t> corner_codes = added_corners;
  tbb::parallel_sort(corner_codes.begin(), corner_codes.end());
  corner_codes.erase(std::unique(corner_codes.begin(), corner_codes.end()), corner_codes.end());
  std::vector<std::uint64_t> born;
  for (const std::uint64_t c : corner_codes)
    if (!std::binary_search(known.codes.begin(), known.codes.end(), c)) born.push_back(c);
  const std::size_t nv = known.codes.size() + born.size();
  check_vertex_count(nv);

  // The known and the new codes merged; known vertex k moves to moved[k].
  OctreeVertices v;
  v.codes.resize(nv);
  v.coords.resize(nv);
  v.points.resize(nv);
  v.region.assign(nv, kNoIndex);
  v.hanging.assign(nv, 0);
  std::vector<Index> moved(known.codes.size());
  fresh.clear();
  for (std::size_t to = 0, k = 0, b = 0; to < nv; ++to) {
    if (b < born.size() && (k == known.codes.size() || born[b] < known.codes[k])) {
      v.codes[to] = born[b++];
      v.coords[to] = morton_decode(v.codes[to]);
      v.points[to] = tree.world(v.coords[to]);
      fresh.push_back(static_cast<Index>(to));
    } else {
      moved[k] = static_cast<Index>(to);
      v.codes[to] = known.codes[k];
      v.coords[to] = known.coords[k];
      v.points[to] = known.points[k];
      v.region[to] = known.region[k];
      v.hanging[to] = known.hanging[k];
      ++k;
    }
  }

  v.leaf_corners.resize(n);
  clear_leaf_midpoints(v, n);
  const auto renumber = [&moved](Index x) { return x == kNoIndex ? kNoIndex : moved[x]; };
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t j) {
    const Index i = same[j];
    if (i == kNoIndex) return;
    for (int c = 0; c < 8; ++c) v.leaf_corners[j][c] = moved[known.leaf_corners[i][c]];
    for (int e = 0; e < 12; ++e) v.leaf_edge_mid[j][e] = renumber(known.leaf_edge_mid[i][e]);
    for (int f = 0; f < 6; ++f) v.leaf_face_centre[j][f] = renumber(known.leaf_face_centre[i][f]);
  });
  tbb::parallel_for(std::size_t{0}, added.size(), [&](std::size_t k) {
    for (int c = 0; c < 8; ++c) v.leaf_corners[added[k]][c] = index_of(v.codes, added_corners[8 * k + c]);
  });
  // Hanging or not, and whose mid-edge or face-centre vertex, changes only for the corners of
  // the new leaves: any leaf finer than a new leaf is new too (2:1 balance).
  std::vector<Index> around(8 * added.size());
  for (std::size_t k = 0; k < added.size(); ++k)
    for (int c = 0; c < 8; ++c) around[8 * k + c] = v.leaf_corners[added[k]][c];
  tbb::parallel_sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());
  tbb::parallel_for(std::size_t{0}, around.size(), [&](std::size_t k) {
    v.hanging[around[k]] = 0;  // classify_vertex leaves it alone where nothing can hang
    classify_vertex(tree, around[k], v.coords[around[k]], v);
  });
  return v;
}

}  // namespace volmesh
