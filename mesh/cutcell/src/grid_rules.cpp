// The extra refinement rules on the grid of one pass: the first two (extra_rules.hpp) from
// the grid's vertex and edge tables, the hidden-feature rule from its edge points' normals.
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>

#include "cut_grid.hpp"
#include "extra_rules.hpp"

namespace volmesh::cutcell {

std::vector<Index> leaves_by_extra_rules(const Grid& grid, int max_level, double clearance, const LeafMask& among) {
  const Octree& tree = *grid.tree;
  const OctreeVertices& v = grid.vertices;
  // Per leaf tested, the crossings along its most crossed edge; -1 for the others.
  std::vector<int> most_crossed(tree.num_leaves(), -1);
  tbb::parallel_for(Index{0}, tree.num_leaves(), [&](Index i) {
    if (!grid.cut[i] || tree.leaf(i).level >= max_level || !marked(among, i)) return;
    int most = 0;
    for (int e = 0; e < 12; ++e) {
      const Index a = v.leaf_corners[i][kEdgeCorners[e][0]], b = v.leaf_corners[i][kEdgeCorners[e][1]];
      const Index m = v.leaf_edge_mid[i][e];
      const int crossings = m == kNoIndex ? grid.edge_crossings[grid.find_edge(a, b)]
                                          : grid.edge_crossings[grid.find_edge(a, m)] +
                                                grid.edge_crossings[grid.find_edge(m, b)];
      most = std::max(most, crossings);
    }
    most_crossed[i] = most;
  });
  RuleCandidates candidates;
  for (Index i = 0; i < tree.num_leaves(); ++i) {
    if (most_crossed[i] < 0) continue;
    candidates.add_leaf(i, most_crossed[i]);
    for (int f = 0; f < 6; ++f)
      if (const Index centre = v.leaf_face_centre[i][f]; centre != kNoIndex)
        candidates.add_transition_face(f, v.points[centre], grid.leaf_size(i));
  }
  return leaves_selected(candidates, *grid.domain, clearance);
}

namespace {

// The normals at a leaf's exact edge points (on transition faces, at its children's edges),
// each oriented from the lower region into the higher.
void edge_point_normals(const Grid& grid, Index leaf, std::vector<Vec3>& out) {
  const OctreeVertices& v = grid.vertices;
  out.clear();
  const auto add = [&](Index a, Index b) {
    const Index edge = grid.find_edge(a, b);
    if (edge == kNoIndex || !grid.edge_point[edge].exact) return;
    // An edge point's normal runs from its first vertex's region into the other's.
    const auto [first, second] = grid.edges[edge];
    const Vec3& n = grid.edge_point[edge].normal;
    out.push_back(grid.region[first] < grid.region[second] ? n : Vec3(-n));
  };
  for (int e = 0; e < 12; ++e) {
    const Index a = v.leaf_corners[leaf][kEdgeCorners[e][0]], b = v.leaf_corners[leaf][kEdgeCorners[e][1]];
    if (const Index m = v.leaf_edge_mid[leaf][e]; m == kNoIndex) {
      add(a, b);
    } else {
      add(a, m);
      add(m, b);
    }
  }
}

}  // namespace

std::vector<Index> leaves_hiding_features(const Grid& grid, int max_level, double theta,
                                          const LeafMask& among) {
  const Octree& tree = *grid.tree;
  const OctreeVertices& v = grid.vertices;
  // The cut leaves whose edge points see one smooth sheet (normals pairwise within theta):
  // elsewhere the leaf's feature points and splits already follow the bends its edges show.
  std::vector<Index> candidates;
  for (Index i = 0; i < tree.num_leaves(); ++i)
    if (grid.cut[i] && tree.leaf(i).level < max_level && marked(among, i)) candidates.push_back(i);
  std::vector<std::vector<Vec3>> normals(candidates.size());
  tbb::parallel_for(std::size_t{0}, candidates.size(), [&](std::size_t k) {
    edge_point_normals(grid, candidates[k], normals[k]);
    for (const Vec3& m : normals[k])
      for (const Vec3& n : normals[k])
        if (m.dot(n) < theta) {
          normals[k].clear();
          return;
        }
  });
  // Through each such leaf's centre, the two axis segments most nearly along its sheet: the
  // third crosses the sheet itself.
  std::vector<std::size_t> owner;  // into candidates, per segment
  std::vector<Vec3> from, to;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    if (normals[k].empty()) continue;
    const Index i = candidates[k];
    const Vec3 centre = 0.5 * (v.points[v.leaf_corners[i][0]] + v.points[v.leaf_corners[i][7]]);
    const double half = 0.5 * grid.leaf_size(i);
    Vec3 mean = Vec3::Zero();
    for (const Vec3& n : normals[k]) mean += n;
    int across = 0;
    mean.cwiseAbs().maxCoeff(&across);
    for (int axis = 0; axis < 3; ++axis) {
      if (axis == across) continue;
      owner.push_back(k);
      from.push_back(centre - half * Vec3::Unit(axis));
      to.push_back(centre + half * Vec3::Unit(axis));
    }
  }
  std::vector<std::vector<Crossing>> hits;
  grid.domain->crossings(from, to, hits);
  std::vector<std::uint8_t> flag(candidates.size(), 0);
  for (std::size_t s = 0; s < owner.size(); ++s) {
    const std::vector<Vec3>& sheet = normals[owner[s]];
    for (const Crossing& c : hits[s]) {
      if (c.before == c.after) continue;
      const Vec3 n = c.before < c.after ? c.normal : Vec3(-c.normal);
      if (std::none_of(sheet.begin(), sheet.end(), [&](const Vec3& m) { return m.dot(n) >= theta; }))
        flag[owner[s]] = 1;
    }
  }
  std::vector<Index> out;
  for (std::size_t k = 0; k < candidates.size(); ++k)
    if (flag[k]) out.push_back(candidates[k]);
  return out;
}


}  // namespace volmesh::cutcell
