#include "flips.hpp"

#include <algorithm>
#include <limits>
#include <map>

#include "min_sine.hpp"
#include "predicates.hpp"

namespace volmesh::tet::front {

namespace {

// Rings larger than this are left alone: the triangulations grow as Catalan numbers and
// such edges are rare in a mesh of target size h.
constexpr int kMaxRing = 7;
// A change must raise the minimum quality by more than this (a fraction of the best, 0.943):
// rounding noise never counts as a gain, so that the passes end.
constexpr double kMinGain = 1e-9;

// Only edges shorter than this fraction of the mean edge at the node are collapsed, so that
// the mesh keeps its size: the short edges are those the fallback's cavity mesh and cones make.
constexpr double kShortEdge = 0.6;

constexpr double kWorst = -std::numeric_limits<double>::max();

double min_quality(const LiveMesh& mesh, const std::vector<Index>& tets) {
  double q = std::numeric_limits<double>::max();
  for (const Index t : tets) q = std::min(q, mesh.quality(t));
  return q;
}

bool all_positive(const LiveMesh& mesh, const std::vector<Tet>& tets) {
  for (const Tet& t : tets)
    if (!positive(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3])))
      return false;
  return true;
}

double quality(const LiveMesh& mesh, Index a, Index b, Index c, Index d) {
  return min_sine(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d));
}

// The link of edge ab as a closed polygon u_0 … u_{n-1} with every (a, b, u_i, u_{i+1})
// positive; empty when the ring is open (a boundary edge) or passes a kept face.
std::vector<Index> closed_link(const LiveMesh& mesh, Index a, Index b,
                               const std::vector<Index>& ring) {
  std::map<Index, Index> next;
  for (const Index t : ring) {
    const Tet& s = mesh.tet(t);
    std::array<Index, 2> cd;
    int k = 0;
    for (const Index v : s)
      if (v != a && v != b) cd[k++] = v;
    if (!even_order(s, a, b, cd[0], cd[1])) std::swap(cd[0], cd[1]);
    if (!next.emplace(cd[0], cd[1]).second) return {};
  }
  std::vector<Index> link{next.begin()->first};
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto it = next.find(link.back());
    if (it == next.end()) return {};
    if (it->second == link.front()) break;
    link.push_back(it->second);
  }
  if (link.size() != ring.size() || next.at(link.back()) != link.front()) return {};
  for (const Index u : link)
    if (mesh.kept(a, b, u)) return {};
  return link;
}

}  // namespace

int remove_edge(LiveMesh& mesh, Index a, Index b) {
  const std::vector<Index> ring = mesh.tets_with(a, b);
  const int n = static_cast<int>(ring.size());
  if (n < 3 || n > kMaxRing) return 0;
  const std::vector<Index> u = closed_link(mesh, a, b, ring);
  if (u.empty()) return 0;
  // best[i][j]: the best minimum quality over the triangulations of u_i … u_j (i < j), with
  // the tets (u_i, u_k, u_j, b) and (u_k, u_i, u_j, a) of each triangle i < k < j.
  std::array<std::array<double, kMaxRing>, kMaxRing> best;
  std::array<std::array<int, kMaxRing>, kMaxRing> split{};
  for (int i = 0; i + 1 < n; ++i) best[i][i + 1] = std::numeric_limits<double>::max();
  for (int span = 2; span < n; ++span)
    for (int i = 0; i + span < n; ++i) {
      const int j = i + span;
      best[i][j] = kWorst;
      for (int k = i + 1; k < j; ++k) {
        const double q = std::min({best[i][k], best[k][j], quality(mesh, u[i], u[k], u[j], b),
                                   quality(mesh, u[k], u[i], u[j], a)});
        if (q > best[i][j]) {
          best[i][j] = q;
          split[i][j] = k;
        }
      }
    }
  if (!(best[0][n - 1] > min_quality(mesh, ring) + kMinGain)) return 0;
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
  if (!all_positive(mesh, fresh)) return 0;
  mesh.replace(ring, fresh);
  return n;
}

bool flip_2_3(LiveMesh& mesh, Index t, int face) {
  const Tet& s = mesh.tet(t);
  Index x = s[kTetFaces[face][0]], y = s[kTetFaces[face][1]], z = s[kTetFaces[face][2]];
  if (mesh.kept(x, y, z)) return false;
  const std::vector<Index> pair = mesh.tets_with(x, y, z);
  if (pair.size() != 2) return false;
  const Index other = pair[0] == t ? pair[1] : pair[0];
  Index d = 0, e = 0;
  for (const Index v : s)
    if (v != x && v != y && v != z) d = v;
  for (const Index v : mesh.tet(other))
    if (v != x && v != y && v != z) e = v;
  // d above the face (x, y, z), e below: the new tets turn around the edge e → d.
  if (!even_order(s, x, y, z, d)) std::swap(x, y);
  const std::vector<Tet> fresh{{e, d, x, y}, {e, d, y, z}, {e, d, z, x}};
  double q = std::numeric_limits<double>::max();
  for (const Tet& n : fresh) q = std::min(q, quality(mesh, n[0], n[1], n[2], n[3]));
  if (!(q > min_quality(mesh, pair) + kMinGain)) return false;
  if (!all_positive(mesh, fresh)) return false;
  mesh.replace(pair, fresh);
  return true;
}

bool collapse_edge(LiveMesh& mesh, Index a, Index b) {
  if (!mesh.movable(a)) return false;
  const std::vector<Index> star = mesh.incident(a);
  double sum = 0.0;
  int edges = 0;
  for (const Index t : star)
    for (const Index v : mesh.tet(t))
      if (v != a) {
        sum += (mesh.point(v) - mesh.point(a)).norm();
        ++edges;
      }
  if (!((mesh.point(b) - mesh.point(a)).norm() < kShortEdge * sum / edges)) return false;
  std::vector<Tet> fresh;
  double q = std::numeric_limits<double>::max();
  for (const Index t : star) {
    Tet n = mesh.tet(t);
    if (std::find(n.begin(), n.end(), b) != n.end()) continue;
    std::replace(n.begin(), n.end(), a, b);
    q = std::min(q, quality(mesh, n[0], n[1], n[2], n[3]));
    fresh.push_back(n);
  }
  if (fresh.size() == star.size()) return false;  // b is no neighbour
  if (!(q > min_quality(mesh, star) + kMinGain)) return false;
  if (!all_positive(mesh, fresh)) return false;
  mesh.replace(star, fresh);
  return true;
}

}  // namespace volmesh::tet::front
