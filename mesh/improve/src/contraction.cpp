// Edge contraction: the tets around the edge go, the others of the gone point's star take the
// kept point instead. The link condition (the links of the two points meet only in the link
// of the edge) keeps the mesh a manifold; the exact test keeps it positive.
#include <algorithm>
#include <iterator>
#include <limits>
#include <map>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "exact.hpp"
#include "quality.hpp"
#include "topology.hpp"

namespace volmesh::improve {

namespace {

using Point2 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;

// The point at infinity that the boundary faces are coned to, so that the link condition
// below also guards the boundary: contracting an inner edge between two boundary points
// would pinch the domain.
constexpr Index kOmega = kNoIndex;

using Edge = std::array<Index, 2>;
using Triangle = std::array<Index, 3>;

struct Link {
  std::vector<Index> vertices;
  std::vector<Edge> edges;
  std::vector<Triangle> triangles;
  void add(Index a, Index b, Index c) {
    std::array<Index, 3> t{a, b, c};
    std::sort(t.begin(), t.end());
    vertices.insert(vertices.end(), t.begin(), t.end());
    edges.push_back({t[0], t[1]});
    edges.push_back({t[0], t[2]});
    edges.push_back({t[1], t[2]});
    triangles.push_back(t);
  }
  void finish() {
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    std::sort(triangles.begin(), triangles.end());
    triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
  }
};

// The faces of tet t holding v that are on the boundary (no tet across), as the two other
// corners.
std::vector<Edge> boundary_faces_at(const TetComplex& mesh, Index t, Index v) {
  std::vector<Edge> out;
  const Tet& c = mesh.tet(t);
  for (const auto& f : kTetFaces) {
    const Index p = c[f[0]], q = c[f[1]], r = c[f[2]];
    if ((p != v && q != v && r != v) || mesh.across(t, p, q, r) != kNoIndex) continue;
    out.push_back(p == v ? Edge{q, r} : q == v ? Edge{p, r} : Edge{p, q});
  }
  return out;
}

Link link_of(const TetComplex& mesh, Index v) {
  Link link;
  for (const Index t : mesh.star(v)) {
    Triangle opposite{};
    int k = 0;
    for (const Index w : mesh.tet(t))
      if (w != v) opposite[k++] = w;
    link.add(opposite[0], opposite[1], opposite[2]);
    for (const auto& [p, q] : boundary_faces_at(mesh, t, v)) link.add(p, q, kOmega);
  }
  link.finish();
  return link;
}

template <class T>
std::vector<T> common(const std::vector<T>& x, const std::vector<T>& y) {
  std::vector<T> out;
  std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::back_inserter(out));
  return out;
}

// The link condition with the boundary coned to kOmega: the links of a and b meet exactly in
// the link of edge ab, which keeps the mesh a manifold with the same boundary topology.
bool link_condition(const TetComplex& mesh, Index a, Index b, const std::vector<Index>& ring) {
  Link edge;
  for (const Index t : ring) {
    const auto [c, d] = opposite_edge(mesh.tet(t), a, b);
    edge.vertices.insert(edge.vertices.end(), {c, d});
    edge.edges.push_back({std::min(c, d), std::max(c, d)});
    for (const auto& [p, q] : boundary_faces_at(mesh, t, a))
      if (p == b || q == b) {
        const Index c2 = p == b ? q : p;
        edge.vertices.insert(edge.vertices.end(), {c2, kOmega});
        edge.edges.push_back({kOmega, c2});
      }
  }
  edge.finish();
  const Link la = link_of(mesh, a), lb = link_of(mesh, b);
  return common(la.vertices, lb.vertices) == edge.vertices &&
         common(la.edges, lb.edges) == edge.edges && common(la.triangles, lb.triangles).empty();
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

// Where `kept` lies in the closure of the triangle or edge that sliding point `gone` lies in:
// the same triangle or edge, an edge of that triangle, or one of their corners.
bool within_carrier(const TetComplex& mesh, Index gone, Index kept) {
  const Slide& s = mesh.slide(gone);
  const int corners = s.kind == SlideKind::Plane ? 3 : 2;
  const auto is_corner = [&](const Vec3& p) {
    return std::find(s.corners.begin(), s.corners.begin() + corners, p) != s.corners.begin() + corners;
  };
  if (is_corner(mesh.point(kept))) return true;
  if (mesh.freedom(kept) != Freedom::Slides) return false;
  const Slide& k = mesh.slide(kept);
  if (k.kind == SlideKind::Plane)
    return s.kind == SlideKind::Plane && std::is_permutation(k.corners.begin(), k.corners.end(),
                                                             s.corners.begin());
  return k.kind == SlideKind::Line && is_corner(k.corners[0]) && is_corner(k.corners[1]);
}

// The sign of triangle abc's orientation seen along the axis of n's largest component, exact.
int projected_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& n) {
  int axis = 0;
  n.cwiseAbs().maxCoeff(&axis);
  const auto plane = [&](const Vec3& p) {
    return Point2(p[(axis + 1) % 3], p[(axis + 2) % 3]);
  };
  return static_cast<int>(CGAL::orientation(plane(a), plane(b), plane(c)));
}

// Whether the boundary faces around `gone` keep their side when `kept` takes its place:
// each new face seen along its old normal turns the same way, so the surface does not fold.
bool boundary_kept(const TetComplex& mesh, Index gone, Index kept) {
  for (const Index t : mesh.star(gone))
    for (const auto& [p, q] : boundary_faces_at(mesh, t, gone)) {
      if (p == kept || q == kept) continue;
      const Vec3 &g = mesh.point(gone), &a = mesh.point(p), &b = mesh.point(q);
      const Vec3 n = (a - g).cross(b - g);
      const int before = projected_sign(g, a, b, n);
      if (before == 0 || projected_sign(mesh.point(kept), a, b, n) != before) return false;
    }
  return true;
}

// The tets of gone's star without kept, gone renamed kept.
std::vector<Tet> renamed_star(const TetComplex& mesh, Index gone, Index kept) {
  std::vector<Tet> fresh;
  for (const Index t : mesh.star(gone)) {
    if (holds(mesh.tet(t), kept)) continue;
    Tet n = mesh.tet(t);
    std::replace(n.begin(), n.end(), gone, kept);
    fresh.push_back(n);
  }
  return fresh;
}

}  // namespace

std::optional<double> contraction_quality(const TetComplex& mesh, Index gone, Index kept) {
  const Freedom freedom = mesh.freedom(gone);
  if (freedom == Freedom::Pinned || (freedom == Freedom::Slides && !within_carrier(mesh, gone, kept)))
    return std::nullopt;
  const std::vector<Index> ring = mesh.tets_with(gone, kept);
  if (ring.empty()) return std::nullopt;
  const std::vector<Tet> fresh = renamed_star(mesh, gone, kept);
  if (!mesh.all_positive(fresh) || !link_condition(mesh, gone, kept, ring)) return std::nullopt;
  if (freedom == Freedom::Slides && !boundary_kept(mesh, gone, kept)) return std::nullopt;
  return mesh.min_quality_of(fresh);
}

bool merge_allowed(const TetComplex& mesh, Index gone, Index kept) {
  const std::vector<Index> ring = mesh.tets_with(gone, kept);
  return !ring.empty() && link_condition(mesh, gone, kept, ring);
}

void contract(TetComplex& mesh, Index gone, Index kept) {
  // Region by region: a merged interface point has tets on both sides.
  std::map<Index, std::pair<std::vector<Index>, std::vector<Tet>>> by_region;
  for (const Index t : mesh.star(gone)) {
    auto& [old, fresh] = by_region[mesh.region(t)];
    old.push_back(t);
    if (holds(mesh.tet(t), kept)) continue;
    Tet n = mesh.tet(t);
    std::replace(n.begin(), n.end(), gone, kept);
    fresh.push_back(n);
  }
  mesh.rename_fixed(gone, kept);
  for (const auto& [region, change] : by_region) mesh.replace(change.first, change.second);
}

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
  const std::vector<Tet> fresh = renamed_star(mesh, gone, kept);
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
