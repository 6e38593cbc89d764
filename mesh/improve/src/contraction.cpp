// Edge contraction: the tets around the edge go, the others of the gone point's star take the
// kept point instead. The link condition (the links of the two points meet only in the link
// of the edge) keeps the mesh a manifold; the exact test keeps it positive.
#include <algorithm>
#include <limits>

#include "exact.hpp"

#include "quality.hpp"
#include "topology.hpp"

namespace volmesh::improve {

namespace {

std::vector<Index> neighbours(const TetComplex& mesh, Index v) {
  std::vector<Index> out;
  for (const Index t : mesh.star(v))
    for (const Index w : mesh.tet(t))
      if (w != v) out.push_back(w);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool link_condition(const TetComplex& mesh, Index a, Index b, const std::vector<Index>& ring) {
  std::vector<Index> edge_link;
  for (const Index t : ring)
    for (const Index w : mesh.tet(t))
      if (w != a && w != b) edge_link.push_back(w);
  std::sort(edge_link.begin(), edge_link.end());
  edge_link.erase(std::unique(edge_link.begin(), edge_link.end()), edge_link.end());
  const std::vector<Index> na = neighbours(mesh, a), nb = neighbours(mesh, b);
  std::vector<Index> common;
  std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
  std::erase(common, a);
  std::erase(common, b);
  if (common != edge_link) return false;
  // Every edge vw in both links must be in the edge's link: a tet (a, b, v, w).
  for (const Index t : mesh.star(a)) {
    const Tet& s = mesh.tet(t);
    if (holds(s, b)) continue;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Index v = s[i], w = s[j];
        if (v == a || w == a || mesh.tets_with(b, v, w).empty()) continue;
        const bool in_ring = std::any_of(ring.begin(), ring.end(), [&](Index r) {
          return holds(mesh.tet(r), v) && holds(mesh.tet(r), w);
        });
        if (!in_ring) return false;
      }
  }
  return true;
}

std::array<Vec3, 4> corners_with(const TetComplex& mesh, const Tet& t, Index kept, const Vec3& p) {
  std::array<Vec3, 4> q;
  for (int k = 0; k < 4; ++k) q[k] = t[k] == kept ? p : mesh.point(t[k]);
  return q;
}

// The tets' smallest quality with `kept` at p, or any value at most `floor` once it is known
// to be no more.
double worst_with(const TetComplex& mesh, const std::vector<Tet>& tets, Index kept, const Vec3& p,
                  double floor) {
  double worst = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < tets.size() && worst > floor; ++i) {
    const auto q = corners_with(mesh, tets[i], kept, p);
    worst = std::min(worst, tet_quality(q[0], q[1], q[2], q[3]));
  }
  return worst;
}

bool positive_with(const TetComplex& mesh, const std::vector<Tet>& tets, Index kept, const Vec3& p) {
  return std::all_of(tets.begin(), tets.end(), [&](const Tet& t) {
    const auto q = corners_with(mesh, t, kept, p);
    return positive(q[0], q[1], q[2], q[3]);
  });
}

}  // namespace

bool contract_edge(TetComplex& mesh, Index gone, Index kept) {
  if (mesh.freedom(gone) != Freedom::Free) return false;
  const std::vector<Index> ring = mesh.tets_with(gone, kept);
  if (ring.empty()) return false;
  const std::vector<Index> old = mesh.star(gone);
  std::vector<Index> kept_only;  // the kept point's tets that stay
  std::vector<Tet> kept_tets;
  for (const Index t : mesh.star(kept))
    if (!holds(mesh.tet(t), gone)) {
      kept_only.push_back(t);
      kept_tets.push_back(mesh.tet(t));
    }
  const double before = std::min(mesh.min_quality(old), mesh.min_quality(kept_only));
  std::vector<Tet> fresh;
  for (const Index t : old) {
    if (holds(mesh.tet(t), kept)) continue;
    Tet n = mesh.tet(t);
    std::replace(n.begin(), n.end(), gone, kept);
    fresh.push_back(n);
  }
  // The kept point where it is, or at the midpoint when it may move.
  const Vec3 at = mesh.point(kept);
  std::vector<Vec3> places{at};
  if (mesh.freedom(kept) == Freedom::Free) places.push_back(0.5 * (at + mesh.point(gone)));
  const double floor = before + kMinGain;
  for (const Vec3& p : places) {
    const double after =
        p == at ? std::min(mesh.min_quality_of(fresh, floor), mesh.min_quality(kept_only))
                : std::min(worst_with(mesh, fresh, kept, p, floor),
                           worst_with(mesh, kept_tets, kept, p, floor));
    if (!raises(after, before) || !positive_with(mesh, fresh, kept, p) ||
        (p != at && !positive_with(mesh, kept_tets, kept, p)) ||
        !link_condition(mesh, gone, kept, ring))
      continue;
    if (p != at) mesh.move(kept, p);
    mesh.replace(old, fresh);
    return true;
  }
  return false;
}

}  // namespace volmesh::improve
