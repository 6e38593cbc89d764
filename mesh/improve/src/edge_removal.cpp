// Edge removal (Klingner and Shewchuk, after Shewchuk's "Two discrete optimization
// algorithms for the topological improvement of tetrahedral meshes").
#include <limits>
#include <map>

#include "quality.hpp"
#include "topology.hpp"

namespace volmesh::improve {

namespace {

// The link of edge ab as a closed polygon u_0 … u_{n-1} with every (a, b, u_i, u_{i+1})
// positive; empty when the ring is open (a boundary edge) or holds a fixed face.
std::vector<Index> closed_link(const TetComplex& mesh, Index a, Index b,
                               const std::vector<Index>& ring) {
  std::map<Index, Index> next;
  for (const Index t : ring) {
    const auto [c, d] = opposite_edge(mesh.tet(t), a, b);
    if (!next.emplace(c, d).second) return {};
  }
  std::vector<Index> link{next.begin()->first};
  while (link.size() < ring.size()) {
    const auto it = next.find(link.back());
    if (it == next.end() || it->second == link.front()) return {};
    link.push_back(it->second);
  }
  const auto last = next.find(link.back());
  if (last == next.end() || last->second != link.front()) return {};
  for (const Index u : link)
    if (mesh.fixed_face(a, b, u)) return {};
  return link;
}

}  // namespace

int remove_edge(TetComplex& mesh, Index a, Index b) {
  const std::vector<Index> ring = mesh.tets_with(a, b);
  const int n = static_cast<int>(ring.size());
  if (n < 3 || n > kMaxRing) return 0;
  const std::vector<Index> u = closed_link(mesh, a, b, ring);
  if (u.empty()) return 0;
  // best[i][j]: the largest smallest quality over the triangulations of the sub-polygon
  // u_i … u_j, each triangle (i, k, j) giving the tets (u_i, u_k, u_j, b) and
  // (u_k, u_i, u_j, a); split[i][j] the k of the best.
  constexpr double kNone = std::numeric_limits<double>::infinity();
  std::array<std::array<double, kMaxRing>, kMaxRing> best{};
  std::array<std::array<int, kMaxRing>, kMaxRing> split{};
  const auto q = [&](Index p0, Index p1, Index p2, Index p3) {
    return tet_quality(mesh.point(p0), mesh.point(p1), mesh.point(p2), mesh.point(p3));
  };
  for (int i = 0; i + 1 < n; ++i) best[i][i + 1] = kNone;
  for (int span = 2; span < n; ++span)
    for (int i = 0; i + span < n; ++i) {
      const int j = i + span;
      best[i][j] = kFlatQuality;
      for (int k = i + 1; k < j; ++k) {
        const double value = std::min({best[i][k], best[k][j], q(u[i], u[k], u[j], b),
                                       q(u[k], u[i], u[j], a)});
        if (value > best[i][j]) {
          best[i][j] = value;
          split[i][j] = k;
        }
      }
    }
  if (!raises(best[0][n - 1], mesh.min_quality(ring))) return 0;
  std::vector<Tet> fresh;
  std::vector<std::array<int, 2>> pending{{0, n - 1}};
  while (!pending.empty()) {
    const auto [i, j] = pending.back();
    pending.pop_back();
    if (j - i < 2) continue;
    const int k = split[i][j];
    fresh.push_back({u[i], u[k], u[j], b});
    fresh.push_back({u[k], u[i], u[j], a});
    pending.push_back({i, k});
    pending.push_back({k, j});
  }
  if (!mesh.all_positive(fresh)) return 0;
  mesh.replace(ring, fresh);
  return n;
}

}  // namespace volmesh::improve
