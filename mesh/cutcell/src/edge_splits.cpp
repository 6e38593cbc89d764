// An edge still crossed twice at the deepest level, where a junction line or a sharp edge of
// the boundary passes beside it, keeps both crossings: a vertex of the region between them
// splits it into two edges crossed once each. One crossing for both would put the junction
// on the edge, off by up to the distance between the crossings (first order).
#include <algorithm>

#include "cut_grid.hpp"

namespace volmesh::cutcell {
namespace {

// Appends the edge a-b (a < b) crossed once, at `point`, normal from a's region into b's.
void add_edge(Grid& grid, Index a, Index b, const Vec3& point, const Vec3& normal) {
  grid.edge_index.insert(edge_key(a, b), static_cast<Index>(grid.edges.size()));
  grid.edges.push_back({a, b});
  grid.edge_crossings.push_back(1);
  grid.edge_point.push_back({point, normal, true});
  grid.split_vertex.push_back(kNoIndex);
}

}  // namespace

void split_doubly_crossed_edges(Grid& grid, double min_gap) {
  const std::size_t ne = grid.edges.size();
  std::vector<std::size_t> candidates;
  std::vector<Vec3> from, to;
  for (std::size_t e = 0; e < ne; ++e) {
    const auto [a, b] = grid.edges[e];
    if (grid.edge_crossings[e] != 2 || grid.region[a] == grid.region[b]) continue;
    candidates.push_back(e);
    from.push_back(grid.position[a]);
    to.push_back(grid.position[b]);
  }
  std::vector<std::vector<Crossing>> hits;
  grid.domain->crossings(from, to, hits);
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    std::vector<Crossing>& h = hits[k];
    h.erase(std::remove_if(h.begin(), h.end(), [](const Crossing& c) { return c.before == c.after; }), h.end());
    const std::size_t e = candidates[k];
    const auto [a, b] = grid.edges[e];
    if (h.size() != 2) continue;
    const Crossing &first = h[0], &second = h[1];
    const Index middle = first.after;
    if (first.before != grid.region[a] || second.before != middle || second.after != grid.region[b] ||
        middle == grid.region[a] || middle == grid.region[b])
      continue;
    if (second.t - first.t < min_gap) {
      grid.edge_point[e].pinched = middle;
      continue;
    }
    const Index x = static_cast<Index>(grid.position.size());
    grid.position.push_back(0.5 * (first.point + second.point));
    grid.region.push_back(middle);
    grid.split_vertex[e] = x;
    grid.split_edge.push_back(static_cast<Index>(e));
    add_edge(grid, a, x, first.point, first.normal);
    add_edge(grid, b, x, second.point, -second.normal);
  }
}

std::array<Index, 2> grid_vertex_ends(const Grid& grid, Index v) {
  const Index n = grid.vertices.num_vertices();
  return v < n ? std::array<Index, 2>{v, v} : grid.edges[grid.split_edge[v - n]];
}

}  // namespace volmesh::cutcell
