// The first two extra refinement rules (extra_rules.hpp) between grid passes. A split
// changes the rules' verdict only on the new leaves and on the leaves across their faces and
// edges (whose edges and faces gain midpoint and centre vertices); everywhere else the last
// grid's verdict stands. So after a grid pass has split its leaves, the rules run on those
// leaves alone, their inputs gathered straight from the tree and the domain, and their
// leaves are split, until none applies; the next grid pass then finds nothing more. A grid
// pass rebuilds the whole vertex table and edge list, which a handful of splits does not
// need.
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_sort.h>

#include <algorithm>
#include <map>
#include <optional>

#include "cut_grid.hpp"
#include "extra_rules.hpp"

namespace volmesh::cutcell {
namespace {

// Whether a leaf finer than leaf l touches grid point p, a point on l's boundary (the
// midpoint of one of its edges or the centre of one of its faces): p is then a vertex of the
// grid. Beyond l, p touches one block of l's size per nonempty set of the boundary planes
// through p that it steps across (three for an edge, one for a face); a block holds finer
// leaves exactly when it is subdivided, which any one cell of it shows.
bool finer_leaf_at(const Octree& tree, const OctreeLeaf& l, const GridPoint& p) {
  const std::uint32_t s = l.size();
  std::array<int, 3> plane{};  // per axis: 0 p inside l's extent, -1 on its low side, +1 high
  for (int k = 0; k < 3; ++k) plane[k] = p[k] == l.anchor[k] ? -1 : p[k] == l.anchor[k] + s ? 1 : 0;
  for (int across = 1; across < 8; ++across) {
    GridPoint q = p;
    bool valid = true;
    for (int k = 0; k < 3 && valid; ++k) {
      if (across >> k & 1) {  // the cell beyond the plane: below p on the low side
        valid = plane[k] > 0 ? p[k] < kOctreeGrid : plane[k] < 0 && p[k] > 0;
        if (plane[k] < 0) q[k] = p[k] - 1;
      } else if (plane[k] > 0) {  // the cell on l's side
        q[k] = p[k] - 1;
      }
    }
    if (valid && tree.leaf(tree.leaf_containing(q)).level > l.level) return true;
  }
  return false;
}

GridPoint midpoint(const GridPoint& a, const GridPoint& b) {
  return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

// A leaf's boundary vertices as the grid of the tree has them (leaf_boundary_vertices): its
// corners, the midpoints of edges that a finer leaf touches, the centres of transition faces.
struct LeafVertices {
  std::array<GridPoint, 8> corner;
  std::array<GridPoint, 12> mid;
  std::array<GridPoint, 6> centre;
  std::array<bool, 12> has_mid{};
  std::array<bool, 6> has_centre{};
};

LeafVertices leaf_vertices(const Octree& tree, Index i) {
  const OctreeLeaf& l = tree.leaf(i);
  LeafVertices v;
  for (int c = 0; c < 8; ++c) v.corner[c] = l.corner(c);
  for (int e = 0; e < 12; ++e) {
    v.mid[e] = midpoint(v.corner[kEdgeCorners[e][0]], v.corner[kEdgeCorners[e][1]]);
    v.has_mid[e] = finer_leaf_at(tree, l, v.mid[e]);
  }
  for (int f = 0; f < 6; ++f) {
    v.centre[f] = midpoint(v.corner[kFaceCorners[f][0]], v.corner[kFaceCorners[f][2]]);
    v.has_centre[f] = finer_leaf_at(tree, l, v.centre[f]);
  }
  return v;
}

// Regions and crossing counts known from the last grid (its vertex table and edge memo) and
// from the rounds since: a round queries the domain only for what is new. On a surface the
// queries are most of a round's time.
class Known {
 public:
  Known(const OctreeVertices& vertices, const EdgeMemo& memo) : vertices_(vertices), memo_(memo) {}

  std::optional<Index> region(const GridPoint& p) const {
    if (const Index v = vertices_.find(p); v != kNoIndex) return vertices_.region[v];
    const auto it = regions_.find(morton_encode(p));
    return it == regions_.end() ? std::nullopt : std::optional(it->second);
  }
  void add_region(const GridPoint& p, Index region) { regions_.emplace(morton_encode(p), region); }

  // A fine edge as the grid keys it: its lower end in Morton order first.
  static EdgeMemo::Key key(const GridPoint& a, const GridPoint& b) {
    const std::uint64_t ca = morton_encode(a), cb = morton_encode(b);
    return ca < cb ? EdgeMemo::Key{ca, cb} : EdgeMemo::Key{cb, ca};
  }
  std::optional<int> crossings(const EdgeMemo::Key& k) const {
    const auto before = [](const EdgeMemo::Entry& x, const EdgeMemo::Key& key) { return x.key < key; };
    const auto it = std::lower_bound(memo_.entries.begin(), memo_.entries.end(), k, before);
    if (it != memo_.entries.end() && it->key == k) return it->crossings;
    const auto found = crossings_.find(k);
    return found == crossings_.end() ? std::nullopt : std::optional(found->second);
  }
  void add_crossings(const EdgeMemo::Key& k, int count) { crossings_.emplace(k, count); }

 private:
  const OctreeVertices& vertices_;
  const EdgeMemo& memo_;
  std::map<std::uint64_t, Index> regions_;
  std::map<EdgeMemo::Key, int> crossings_;
};

// What leaves_by_extra_rules selects among `leaves` on a grid of this tree, the rules'
// inputs gathered from the tree and the domain.
std::vector<Index> selected_leaves(const Octree& tree, const Domain& domain, Known& known,
                                   const std::vector<Index>& leaves, int max_level, double clearance) {
  std::vector<Index> below;
  for (Index i : leaves)
    if (tree.leaf(i).level < max_level) below.push_back(i);
  const std::size_t n = below.size();
  std::vector<LeafVertices> verts(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t k) { verts[k] = leaf_vertices(tree, below[k]); });

  // Cut: the boundary vertices' regions differ.
  std::vector<GridPoint> at;
  std::vector<std::size_t> first(n + 1, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const LeafVertices& v = verts[k];
    at.insert(at.end(), v.corner.begin(), v.corner.end());
    for (int e = 0; e < 12; ++e)
      if (v.has_mid[e]) at.push_back(v.mid[e]);
    for (int f = 0; f < 6; ++f)
      if (v.has_centre[f]) at.push_back(v.centre[f]);
    first[k + 1] = at.size();
  }
  // Each point not known yet is queried once, however many leaves share it.
  constexpr std::size_t kKnown = ~std::size_t{0};
  std::vector<Index> region(at.size());
  std::vector<std::size_t> query_of(at.size(), kKnown);
  std::map<std::uint64_t, std::size_t> query_at;
  std::vector<GridPoint> asked;
  for (std::size_t j = 0; j < at.size(); ++j) {
    if (const std::optional<Index> r = known.region(at[j])) {
      region[j] = *r;
      continue;
    }
    const auto [it, fresh] = query_at.emplace(morton_encode(at[j]), asked.size());
    if (fresh) asked.push_back(at[j]);
    query_of[j] = it->second;
  }
  std::vector<Vec3> points(asked.size());
  std::vector<Index> queried(asked.size());
  for (std::size_t q = 0; q < asked.size(); ++q) points[q] = tree.world(asked[q]);
  domain.region(points, queried);
  for (std::size_t q = 0; q < asked.size(); ++q) known.add_region(asked[q], queried[q]);
  for (std::size_t j = 0; j < at.size(); ++j)
    if (query_of[j] != kKnown) region[j] = queried[query_of[j]];
  std::vector<std::size_t> cut;
  for (std::size_t k = 0; k < n; ++k)
    if (std::any_of(region.begin() + first[k], region.begin() + first[k + 1],
                    [&](Index r) { return r != region[first[k]]; }))
      cut.push_back(k);

  // Per cut leaf: its fine edges (two where the leaf edge has a midpoint), each one not
  // known yet queried once, as the grid would, from its lower end.
  struct FineEdge {
    std::size_t leaf;  // in cut
    int edge;
    int crossings = 0;
    std::size_t query = kKnown;
  };
  std::vector<FineEdge> fine;
  std::vector<Vec3> a, b;
  std::vector<EdgeMemo::Key> query_edge;
  std::map<EdgeMemo::Key, std::size_t> edge_query;
  for (std::size_t j = 0; j < cut.size(); ++j) {
    const LeafVertices& v = verts[cut[j]];
    const auto add_edge = [&](const GridPoint& p, const GridPoint& q, int e) {
      FineEdge s{j, e};
      const EdgeMemo::Key key = Known::key(p, q);
      if (const std::optional<int> c = known.crossings(key)) {
        s.crossings = *c;
      } else {
        const auto [it, fresh] = edge_query.emplace(key, a.size());
        if (fresh) {
          a.push_back(tree.world(morton_decode(key.first)));
          b.push_back(tree.world(morton_decode(key.second)));
          query_edge.push_back(key);
        }
        s.query = it->second;
      }
      fine.push_back(s);
    };
    for (int e = 0; e < 12; ++e) {
      const GridPoint &p = v.corner[kEdgeCorners[e][0]], &q = v.corner[kEdgeCorners[e][1]];
      if (v.has_mid[e]) {
        add_edge(p, v.mid[e], e);
        add_edge(v.mid[e], q, e);
      } else {
        add_edge(p, q, e);
      }
    }
  }
  std::vector<std::vector<Crossing>> hits;
  domain.crossings(a, b, hits);
  std::vector<int> query_crossings(a.size(), 0);
  for (std::size_t q = 0; q < a.size(); ++q) {
    query_crossings[q] = transversal_crossings(hits[q]);
    known.add_crossings(query_edge[q], query_crossings[q]);
  }
  std::vector<std::array<int, 12>> crossings(cut.size(), std::array<int, 12>{});
  for (const FineEdge& s : fine) crossings[s.leaf][s.edge] += s.query == kKnown ? s.crossings : query_crossings[s.query];

  RuleCandidates candidates;
  for (std::size_t j = 0; j < cut.size(); ++j) {
    const Index leaf = below[cut[j]];
    candidates.add_leaf(leaf, *std::max_element(crossings[j].begin(), crossings[j].end()));
    const LeafVertices& v = verts[cut[j]];
    for (int f = 0; f < 6; ++f)
      if (v.has_centre[f])
        candidates.add_transition_face(f, tree.world(v.centre[f]), tree.cell_size(tree.leaf(leaf).level));
  }
  return leaves_selected(candidates, domain, clearance);
}

// The leaves that splitting these nodes made: their children still leaves (a child split in
// turn is one of the nodes).
std::vector<Index> new_leaves(const Octree& tree, const std::vector<OctreeLeaf>& split) {
  std::vector<Index> out;
  for (const OctreeLeaf& node : split) {
    const std::uint32_t half = node.size() / 2;
    for (int c = 0; c < 8; ++c) {
      const GridPoint anchor{node.anchor[0] + (c & 1) * half, node.anchor[1] + (c >> 1 & 1) * half,
                             node.anchor[2] + (c >> 2 & 1) * half};
      if (const Index i = tree.find_leaf(anchor, node.level + 1); i != kNoIndex) out.push_back(i);
    }
  }
  return out;
}

// The new leaves and the leaves across their faces and edges.
std::vector<Index> touched_leaves(const Octree& tree, const std::vector<Index>& fresh) {
  // At most four leaves across each face and two along each edge.
  using Around = std::array<Index, 6 * 4 + 12 * 2>;
  std::vector<Around> around(fresh.size());
  tbb::parallel_for(std::size_t{0}, fresh.size(), [&](std::size_t k) {
    Around& out = around[k];
    out.fill(kNoIndex);
    std::size_t n = 0;
    for (int f = 0; f < 6; ++f) {
      const FaceNeighbours nb = tree.face_neighbours(fresh[k], f);
      for (int q = 0; q < nb.count(); ++q) out[n++] = nb.leaves[q];
    }
    for (int e = 0; e < 12; ++e)
      for (Index x : tree.edge_neighbours(fresh[k], e).leaves) out[n++] = x;
  });
  std::vector<Index> out = fresh;
  for (const Around& a : around)
    for (Index x : a)
      if (x != kNoIndex) out.push_back(x);
  tbb::parallel_sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Splits the leaves (and what the 2:1 balance needs); the leaves touched_leaves gives.
std::vector<Index> split_and_touched(Octree& tree, std::vector<Index> leaves) {
  return touched_leaves(tree, new_leaves(tree, split_balanced(tree, std::move(leaves))));
}

void append_nodes(const Octree& tree, const std::vector<Index>& leaves, std::vector<OctreeLeaf>& out) {
  for (Index i : leaves) out.push_back(tree.leaf(i));
}

}  // namespace

ExtraRuleSplits split_by_extra_rules(Octree& tree, const Domain& domain, const OctreeVertices& vertices,
                                     const EdgeMemo& memo, std::vector<Index> leaves, int max_level,
                                     double clearance) {
  Known known(vertices, memo);
  std::sort(leaves.begin(), leaves.end());
  leaves.erase(std::unique(leaves.begin(), leaves.end()), leaves.end());
  ExtraRuleSplits out;
  while (!leaves.empty()) {
    const std::vector<Index> touched = split_and_touched(tree, std::move(leaves));
    ++out.rounds;
    append_nodes(tree, touched, out.touched);
    leaves = selected_leaves(tree, domain, known, touched, max_level, clearance);
  }
  return out;
}

std::vector<OctreeLeaf> split_touching(Octree& tree, std::vector<Index> leaves) {
  std::vector<OctreeLeaf> out;
  if (!leaves.empty()) append_nodes(tree, split_and_touched(tree, std::move(leaves)), out);
  return out;
}

LeafMask leaves_among(const Octree& tree, const std::vector<OctreeLeaf>& nodes) {
  LeafMask mask(tree.num_leaves(), 0);
  for (const OctreeLeaf& node : nodes)
    if (const Index i = tree.find_leaf(node.anchor, node.level); i != kNoIndex) mask[i] = 1;
  return mask;
}

}  // namespace volmesh::cutcell
