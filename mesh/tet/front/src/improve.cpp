#include "improve.hpp"

#include <algorithm>

#include "flips.hpp"
#include "live_mesh.hpp"
#include "smooth.hpp"
#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/quality/tet_metrics.hpp"

namespace volmesh::tet::front {

namespace {

// A bound on the passes; in practice they stop earlier, when one changes nothing.
constexpr int kMaxPasses = 12;
// Tets worse than this quality (sin 30°) are the ones whose edges and faces are flipped and
// whose nodes are smoothed; better ones are left as the front made them.
constexpr double kImproveBelow = 0.5;

struct Extremes {
  double min_dihedral = 180.0, max_radius_edge = 0.0;
};

Extremes extremes(const TetMesh& m) {
  Extremes e;
  for (const auto& c : m.cells) {
    const TetMetrics q = tet_metrics(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]);
    e.min_dihedral = std::min(e.min_dihedral, q.min_dihedral_deg);
    e.max_radius_edge = std::max(e.max_radius_edge, q.radius_edge_ratio);
  }
  return e;
}

// The poor tets, worst first (ties by slot), so that each pass starts where it gains most.
std::vector<Index> poor_tets(const LiveMesh& mesh) {
  std::vector<Index> poor;
  for (Index t = 0; t < mesh.num_slots(); ++t)
    if (mesh.alive(t) && mesh.quality(t) < kImproveBelow) poor.push_back(t);
  std::sort(poor.begin(), poor.end(), [&](Index a, Index b) {
    return mesh.quality(a) != mesh.quality(b) ? mesh.quality(a) < mesh.quality(b) : a < b;
  });
  return poor;
}

void count_flip(ImproveStats& s, int ring) {
  if (ring == 3) ++s.flips_3_2;
  else if (ring == 4) ++s.flips_4_4;
  else ++s.edge_removals;
}

// The tet's edges in lexicographic corner order (01 02 03 12 13 23), not kTetEdges' VTK
// order: the first edge whose removal helps is taken, and equal lengths keep this order, so
// VTK's order would change the meshes made.
constexpr std::array<std::array<int, 2>, 6> kEdgesByCorner = [] {
  std::array<std::array<int, 2>, 6> edges = kTetEdges;
  std::sort(edges.begin(), edges.end());
  return edges;
}();

// Flips around one poor tet: edge removal on its edges, then the 2-3 flip on its faces.
bool flip_around(LiveMesh& mesh, Index t, ImproveStats& s) {
  const Tet corners = mesh.tet(t);
  for (const auto& e : kEdgesByCorner)
    if (const int ring = remove_edge(mesh, corners[e[0]], corners[e[1]])) {
      count_flip(s, ring);
      return true;
    }
  for (int f = 0; f < 4; ++f)
    if (flip_2_3(mesh, t, f)) {
      ++s.flips_2_3;
      return true;
    }
  // The shortest edges first: a poor tet around a short edge is one a collapse removes.
  std::array<int, 6> order{0, 1, 2, 3, 4, 5};
  const auto length = [&](int e) {
    const auto& [a, b] = kEdgesByCorner[e];
    return (mesh.point(corners[a]) - mesh.point(corners[b])).squaredNorm();
  };
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return length(x) < length(y); });
  for (const int e : order) {
    const Index a = corners[kEdgesByCorner[e][0]], b = corners[kEdgesByCorner[e][1]];
    if (collapse_edge(mesh, a, b) || collapse_edge(mesh, b, a)) {
      ++s.collapses;
      return true;
    }
  }
  return false;
}

}  // namespace

ImproveStats improve_mesh(TetMesh& m, Index fixed_nodes,
                          const std::vector<std::array<Index, 3>>& kept) {
  const auto clock = Clock::now();
  ImproveStats s;
  const Extremes before = extremes(m);
  s.min_dihedral_before = before.min_dihedral;
  s.radius_edge_before = before.max_radius_edge;
  LiveMesh mesh(m, fixed_nodes, kept);
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    long long changes = 0;
    for (const Index t : poor_tets(mesh))
      if (mesh.alive(t) && mesh.quality(t) < kImproveBelow) changes += flip_around(mesh, t, s);
    std::vector<Index> nodes;
    for (const Index t : poor_tets(mesh))
      for (const Index v : mesh.tet(t))
        if (mesh.movable(v)) nodes.push_back(v);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    for (const Index v : nodes)
      if (smooth_node(mesh, v)) {
        ++s.nodes_moved;
        ++changes;
      }
    ++s.passes;
    if (changes == 0) break;
  }
  mesh.compact();
  const Extremes after = extremes(m);
  s.min_dihedral_after = after.min_dihedral;
  s.radius_edge_after = after.max_radius_edge;
  s.seconds = seconds_since(clock);
  return s;
}

}  // namespace volmesh::tet::front
