// Vertices, cut leaves and edge interface points of one pass.
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_sort.h>

#include <algorithm>

#include "cut_grid.hpp"
#include "extra_rules.hpp"
#include "tangent_point.hpp"

namespace volmesh::cutcell {
namespace {

// Crossing queries are batched so that the crossing lists of one batch only are in memory.
constexpr std::size_t kBatch = std::size_t{1} << 16;

}  // namespace

Grid make_grid(const Octree& tree, const Domain& domain, const GridSettings& settings,
               const OctreeVertices& known) {
  Grid grid;
  grid.tree = &tree;
  grid.domain = &domain;
  grid.settings = settings;
  grid.vertices = octree_vertices(tree, domain, known);
  grid.position = grid.vertices.points;
  grid.region = grid.vertices.region;
  classify_leaves(grid);
  return grid;
}

void leaf_boundary_vertices(const Grid& grid, Index leaf, std::vector<Index>& out) {
  const OctreeVertices& v = grid.vertices;
  for (Index c : v.leaf_corners[leaf]) out.push_back(c);
  for (Index m : v.leaf_edge_mid[leaf])
    if (m != kNoIndex) out.push_back(m);
  for (Index c : v.leaf_face_centre[leaf])
    if (c != kNoIndex) out.push_back(c);
}

void classify_leaves(Grid& grid) {
  const Index n = grid.tree->num_leaves();
  grid.cut.assign(n, 0);
  tbb::parallel_for(tbb::blocked_range<Index>(0, n), [&](const tbb::blocked_range<Index>& r) {
    std::vector<Index> around;
    for (Index i = r.begin(); i < r.end(); ++i) {
      around.clear();
      leaf_boundary_vertices(grid, i, around);
      const Index r0 = grid.region[around[0]];
      grid.cut[i] = std::any_of(around.begin(), around.end(),
                                [&](Index v) { return grid.region[v] != r0; });
    }
  });
}

LeavesAround leaves_around(const Octree& tree, const GridPoint& p) {
  LeavesAround out;
  for (int octant = 0; octant < 8; ++octant) {
    GridPoint q = p;
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      if (octant >> k & 1) {
        inside = q[k] > 0;
        q[k] -= 1;
      } else {
        inside = q[k] < kOctreeGrid;
      }
    }
    if (!inside) continue;
    const Index leaf = tree.leaf_containing(q);
    if (leaf != kNoIndex && std::find(out.leaf.begin(), out.leaf.begin() + out.count, leaf) == out.leaf.begin() + out.count)
      out.leaf[out.count++] = leaf;
  }
  return out;
}

int quarter_of(const OctreeLeaf& small, const OctreeLeaf& big, int axis) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const int lo = std::min(u, v), hi = std::max(u, v);
  const std::uint32_t s = small.size();
  return static_cast<int>((small.anchor[lo] - big.anchor[lo]) / s +
                          2 * ((small.anchor[hi] - big.anchor[hi]) / s));
}

void find_edge_points(Grid& grid, EdgeMemo& memo) {
  const Octree& tree = *grid.tree;
  const OctreeVertices& v = grid.vertices;
  std::vector<Index> cut_leaves;
  for (Index i = 0; i < tree.num_leaves(); ++i)
    if (grid.cut[i]) cut_leaves.push_back(i);
  std::vector<std::uint64_t> codes(24 * cut_leaves.size(), ~std::uint64_t{0});
  tbb::parallel_for(std::size_t{0}, cut_leaves.size(), [&](std::size_t k) {
    const Index i = cut_leaves[k];
    for (int e = 0; e < 12; ++e) {
      const Index a = v.leaf_corners[i][kEdgeCorners[e][0]], b = v.leaf_corners[i][kEdgeCorners[e][1]];
      const Index m = v.leaf_edge_mid[i][e];
      if (m == kNoIndex) {
        codes[24 * k + 2 * e] = edge_key(a, b);
      } else {
        codes[24 * k + 2 * e] = edge_key(a, m);
        codes[24 * k + 2 * e + 1] = edge_key(m, b);
      }
    }
  });
  tbb::parallel_sort(codes.begin(), codes.end());
  codes.erase(std::unique(codes.begin(), codes.end()), codes.end());
  if (!codes.empty() && codes.back() == ~std::uint64_t{0}) codes.pop_back();

  const std::size_t ne = codes.size();
  grid.edges.resize(ne);
  grid.edge_index = KeyMap(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    grid.edges[e] = {static_cast<Index>(codes[e] >> 32), static_cast<Index>(codes[e] & 0xffffffffu)};
    grid.edge_index.insert(codes[e], static_cast<Index>(e));
  }
  grid.edge_crossings.assign(ne, 0);
  grid.edge_point.assign(ne, EdgePoint{});
  grid.split_vertex.assign(ne, kNoIndex);
  grid.split_edge.clear();

  // Edges whose ends sit at their octree positions with their own regions were most likely
  // met in an earlier pass: their results are taken from the memo, the rest are queried.
  enum : std::uint8_t { moved, nominal, known };
  const auto at_home = [&grid, &v](Index x) {
    return grid.position[x] == v.points[x] && grid.region[x] == v.region[x];
  };
  std::vector<EdgeMemo::Key> keys(ne);
  std::vector<std::uint8_t> state(ne, moved);
  const auto before = [](const EdgeMemo::Entry& x, const EdgeMemo::Key& k) { return x.key < k; };
  tbb::parallel_for(std::size_t{0}, ne, [&](std::size_t e) {
    const auto [p, q] = grid.edges[e];
    if (!at_home(p) || !at_home(q)) return;
    keys[e] = {morton_encode(v.coords[p]), morton_encode(v.coords[q])};
    state[e] = nominal;
    const auto it = std::lower_bound(memo.entries.begin(), memo.entries.end(), keys[e], before);
    if (it == memo.entries.end() || it->key != keys[e]) return;
    if (it->point != kNoIndex) grid.edge_point[e] = memo.points[it->point];
    grid.edge_crossings[e] = it->crossings;
    state[e] = known;
  });
  std::vector<std::size_t> todo;
  for (std::size_t e = 0; e < ne; ++e)
    if (state[e] != known) todo.push_back(e);

  std::vector<Vec3> a, b;
  std::vector<std::vector<Crossing>> hits;
  for (std::size_t start = 0; start < todo.size(); start += kBatch) {
    const std::size_t end = std::min(todo.size(), start + kBatch);
    a.resize(end - start);
    b.resize(end - start);
    for (std::size_t k = start; k < end; ++k) {
      a[k - start] = grid.position[grid.edges[todo[k]][0]];
      b[k - start] = grid.position[grid.edges[todo[k]][1]];
    }
    grid.domain->crossings(a, b, hits);
    tbb::parallel_for(start, end, [&](std::size_t k) {
      const std::size_t e = todo[k];
      const std::vector<Crossing>& h = hits[k - start];
      const Index ra = grid.region[grid.edges[e][0]], rb = grid.region[grid.edges[e][1]];
      // The point is the first crossing out of ra, unless an end lies outside the domain
      // behind a boundary plane parallel to the octree's faces (a box): then the crossing
      // with that plane, so that the box's face stays plane when a layer ends just inside
      // it. On a curved boundary either crossing is as close, and the first keeps the
      // cells around a junction better shaped.
      const auto rank = [ra, rb](const Crossing& c) {
        const bool boundary = ((ra == 0 && c.before == 0) || (rb == 0 && c.after == 0)) &&
                              parallel_to_octree_faces(c.normal);
        return 2 * boundary + (c.before == ra);
      };
      const Crossing* chosen = nullptr;
      for (const Crossing& c : h)
        if (c.before != c.after && (!chosen || rank(c) > rank(*chosen))) chosen = &c;
      const std::uint8_t transversal = transversal_crossings(h);
      grid.edge_crossings[e] = transversal;
      if (ra == rb) return;
      const Vec3 &pa = a[k - start], &pb = b[k - start];
      EdgePoint& point = grid.edge_point[e];
      if (grid.settings.exact && chosen) {
        point.point = chosen->point;
        point.normal = chosen->normal;
        point.exact = transversal == 1 && chosen->before == ra && chosen->after == rb;
      } else {
        point.point = 0.5 * (pa + pb);
        point.normal = grid.domain->normal(point.point);
        if (point.normal.dot(pb - pa) < 0) point.normal = -point.normal;
      }
    });
  }
  // Vertex numbers follow the Morton order, so the edges, sorted by their ends' numbers,
  // come sorted by their ends' codes.
  const auto has_point = [](const EdgePoint& p) {
    return p.exact || p.pinched != kNoIndex || p.point != Vec3::Zero() || p.normal != Vec3::Zero();
  };
  std::vector<EdgeMemo::Entry> entries;
  std::vector<EdgePoint> points;
  entries.reserve(ne - static_cast<std::size_t>(std::count(state.begin(), state.end(), moved)));
  for (std::size_t e = 0; e < ne; ++e) {
    if (state[e] == moved) continue;
    Index point = kNoIndex;
    if (has_point(grid.edge_point[e])) {
      point = static_cast<Index>(points.size());
      points.push_back(grid.edge_point[e]);
    }
    entries.push_back({keys[e], point, grid.edge_crossings[e]});
  }
  memo.entries = std::move(entries);
  memo.points = std::move(points);
}

Index relabel_midpoints(Grid& grid) {
  const OctreeVertices& v = grid.vertices;
  Index relabelled = 0;
  for (Index i = 0; i < grid.tree->num_leaves(); ++i) {
    if (!grid.cut[i]) continue;
    for (int e = 0; e < 12; ++e) {
      const Index m = v.leaf_edge_mid[i][e];
      if (m == kNoIndex) continue;
      const Index ra = grid.region[v.leaf_corners[i][kEdgeCorners[e][0]]];
      const Index rb = grid.region[v.leaf_corners[i][kEdgeCorners[e][1]]];
      if (grid.region[m] != ra && grid.region[m] != rb) {
        grid.region[m] = ra;
        ++relabelled;
      }
    }
  }
  return relabelled;
}

}  // namespace volmesh::cutcell
