// Mesh vertices of the octree: leaf corners deduplicated by Morton code.
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_sort.h>

#include <algorithm>
#include <bit>
#include <string>

#include "vertex_table.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh {

// On a balanced tree a leaf that p lies inside an edge or a face of is one level coarser than
// the finest grid p lies on, and p is the midpoint of its edge (one coordinate off that
// coarser grid) or the centre of its face (two), so a few lookups around p settle it.
void classify_vertex(const Octree& tree, Index id, const GridPoint& p, OctreeVertices& v) {
  int zeros = kOctreeMaxLevel;  // trailing zeros common to the coordinates (0 counts as all)
  for (const std::uint32_t x : p)
    if (x != 0) zeros = std::min(zeros, std::countr_zero(x));
  if (zeros >= kOctreeMaxLevel) return;  // a root corner
  const int level = kOctreeMaxLevel - zeros - 1;  // of the coarser leaves around p
  const std::int64_t big = std::int64_t{2} << zeros, half = std::int64_t{1} << zeros;
  std::array<bool, 3> off;
  int count = 0;
  for (int a = 0; a < 3; ++a) count += off[a] = (p[a] >> zeros & 1) != 0;
  if (count == 3) return;  // the centre of a coarser cell: never on a leaf's boundary

  auto leaf_at = [&](const std::array<std::int64_t, 3>& anchor) {
    for (const std::int64_t x : anchor)
      if (x < 0 || x >= kOctreeGrid) return kNoIndex;
    return tree.find_leaf({static_cast<std::uint32_t>(anchor[0]),
                           static_cast<std::uint32_t>(anchor[1]),
                           static_cast<std::uint32_t>(anchor[2])},
                          level);
  };
  bool hanging = false;
  if (count == 1) {  // the midpoint of an edge along `axis`, shared by four coarser cells
    const int axis = off[0] ? 0 : off[1] ? 1 : 2;
    const int u = axis == 0 ? 1 : 0, v_axis = axis == 2 ? 1 : 2;
    for (int k = 0; k < 4; ++k) {
      const int bu = k & 1, bv = k >> 1;  // the edge's position in the cell
      std::array<std::int64_t, 3> anchor{p[0], p[1], p[2]};
      anchor[axis] -= half;
      anchor[u] -= bu * big;
      anchor[v_axis] -= bv * big;
      const Index leaf = leaf_at(anchor);
      if (leaf == kNoIndex) continue;
      v.leaf_edge_mid[leaf][4 * axis + bu + 2 * bv] = id;
      hanging = true;
    }
  } else {  // the centre of a face normal to `axis`, shared by two coarser cells
    const int axis = !off[0] ? 0 : !off[1] ? 1 : 2;
    for (int side = 0; side < 2; ++side) {  // the face is the cell's low side, then its high
      std::array<std::int64_t, 3> anchor{p[0] - half, p[1] - half, p[2] - half};
      anchor[axis] = p[axis] - side * big;
      const Index leaf = leaf_at(anchor);
      if (leaf == kNoIndex) continue;
      v.leaf_face_centre[leaf][2 * axis + side] = id;
      hanging = true;
    }
  }
  v.hanging[id] = hanging;
}

void check_vertex_count(std::size_t nv) {
  if (nv > static_cast<std::size_t>(kMaxIndex))
    throw InputError("octree: " + std::to_string(nv) + " vertices exceed the index limit " +
                     std::to_string(kMaxIndex) + "; lower the level");
}

void clear_leaf_midpoints(OctreeVertices& v, std::size_t n) {
  std::array<Index, 12> no_mid;
  no_mid.fill(kNoIndex);
  v.leaf_edge_mid.assign(n, no_mid);
  std::array<Index, 6> no_centre;
  no_centre.fill(kNoIndex);
  v.leaf_face_centre.assign(n, no_centre);
}

OctreeVertices octree_vertex_geometry(const Octree& tree) {
  const std::size_t n = tree.leaves().size();
  // Leaves come mostly in complete sibling groups (the eight children of one parent, one
  // after the other in Morton order) whose 64 corners are 27 points: listing each point once
  // per group roughly halves the sort. A unit is such a group or a single leaf.
  std::vector<std::size_t> unit_leaf, unit_entry{0};
  for (std::size_t i = 0; i < n;) {
    const OctreeLeaf& l = tree.leaf(i);
    bool group = l.level > 0 && i + 8 <= n &&
                 ((l.anchor[0] | l.anchor[1] | l.anchor[2]) & (2 * l.size() - 1)) == 0;
    for (std::size_t c = 1; group && c < 8; ++c) group = tree.leaf(i + c).level == l.level;
    unit_leaf.push_back(i);
    unit_entry.push_back(unit_entry.back() + (group ? 27 : 8));
    i += group ? 8 : 1;
  }
  auto is_group = [&](std::size_t u) { return unit_entry[u + 1] - unit_entry[u] == 27; };
  // (code, entry) pairs sorted by code: equal codes are one vertex. Above kWeightShift each
  // entry holds the number of the unit's leaves the point is a corner of.
  constexpr int kWeightShift = 60;
  constexpr std::uint64_t kEntry = (std::uint64_t{1} << kWeightShift) - 1;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> entries(unit_entry.back());
  tbb::parallel_for(std::size_t{0}, unit_leaf.size(), [&](std::size_t u) {
    const OctreeLeaf& l = tree.leaf(unit_leaf[u]);
    const std::size_t e0 = unit_entry[u];
    if (!is_group(u)) {
      for (int k = 0; k < 8; ++k)
        entries[e0 + k] = {morton_encode(l.corner(k)),
                           (e0 + k) | std::uint64_t{1} << kWeightShift};
      return;
    }
    const std::uint32_t s = l.size();
    for (std::uint32_t p = 0; p < 27; ++p) {
      // A point in the middle of the group along an axis is a corner of both children there.
      const int middle = (p % 3 == 1) + (p / 3 % 3 == 1) + (p / 9 == 1);
      const std::uint64_t weight = std::uint64_t{1} << middle;
      entries[e0 + p] = {morton_encode({l.anchor[0] + p % 3 * s, l.anchor[1] + p / 3 % 3 * s,
                                        l.anchor[2] + p / 9 * s}),
                         (e0 + p) | weight << kWeightShift};
    }
  });
  // Equal codes may come in any order: each gets the same vertex id.
  tbb::parallel_sort(entries.begin(), entries.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::uint64_t> codes;
  std::vector<std::uint8_t> corner_of;  // per vertex: the number of leaves it is a corner of
  std::vector<Index> vertex_of(entries.size());
  for (const auto& [code, entry] : entries) {
    if (codes.empty() || codes.back() != code) {
      codes.push_back(code);
      corner_of.push_back(0);
    }
    corner_of.back() += static_cast<std::uint8_t>(entry >> kWeightShift);
    vertex_of[entry & kEntry] = static_cast<Index>(codes.size() - 1);
  }
  entries = {};
  OctreeVertices v;
  v.leaf_corners.resize(n);
  tbb::parallel_for(std::size_t{0}, unit_leaf.size(), [&](std::size_t u) {
    const std::size_t e0 = unit_entry[u];
    if (!is_group(u)) {
      for (int k = 0; k < 8; ++k) v.leaf_corners[unit_leaf[u]][k] = vertex_of[e0 + k];
      return;
    }
    for (int c = 0; c < 8; ++c)
      for (int k = 0; k < 8; ++k) {
        const int p = (c & 1) + (k & 1) + 3 * ((c >> 1 & 1) + (k >> 1 & 1)) +
                      9 * ((c >> 2 & 1) + (k >> 2 & 1));
        v.leaf_corners[unit_leaf[u] + c][k] = vertex_of[e0 + p];
      }
  });
  check_vertex_count(codes.size());

  const std::size_t nv = codes.size();
  v.coords.resize(nv);
  v.points.resize(nv);
  tbb::parallel_for(std::size_t{0}, nv, [&](std::size_t i) {
    v.coords[i] = morton_decode(codes[i]);
    v.points[i] = tree.world(v.coords[i]);
  });

  clear_leaf_midpoints(v, n);
  v.hanging.assign(nv, 0);
  // Each (leaf, edge) has one midpoint and each (leaf, face) one centre, so no two vertices
  // write the same entry. A vertex that is a corner of every leaf around it (of 2^k, k its
  // coordinates inside the root) lies inside no leaf's edge or face: only the others are
  // looked at.
  tbb::parallel_for(std::size_t{0}, nv, [&](std::size_t i) {
    int around = 1;
    for (const std::uint32_t x : v.coords[i]) around <<= (x != 0 && x != kOctreeGrid);
    if (corner_of[i] < around) classify_vertex(tree, static_cast<Index>(i), v.coords[i], v);
  });
  v.codes = std::move(codes);
  return v;
}

OctreeVertices octree_vertices(const Octree& tree, const Domain& domain, const OctreeVertices& known) {
  if (known.num_vertices() == 0) {
    OctreeVertices v = octree_vertex_geometry(tree);
    v.region.resize(v.points.size());
    domain.region(v.points, v.region);
    return v;
  }
  std::vector<Index> fresh;  // the new vertices, whose regions are queried
  OctreeVertices v = refined_vertex_geometry(tree, known, fresh);
  std::vector<Vec3> points(fresh.size());
  for (std::size_t k = 0; k < fresh.size(); ++k) points[k] = v.points[fresh[k]];
  std::vector<Index> regions(fresh.size());
  domain.region(points, regions);
  for (std::size_t k = 0; k < fresh.size(); ++k) v.region[fresh[k]] = regions[k];
  return v;
}

void leaf_face_loop(const OctreeVertices& vertices, Index leaf, int face,
                    std::vector<Index>& out) {
  for (int i = 0; i < 4; ++i) {
    out.push_back(vertices.leaf_corners[leaf][kFaceCorners[face][i]]);
    const Index mid = vertices.leaf_edge_mid[leaf][kFaceEdges[face][i]];
    if (mid != kNoIndex) out.push_back(mid);
  }
}

}  // namespace volmesh
