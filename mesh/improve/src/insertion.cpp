// Vertex insertion: the new point at the bad tet's centroid; the cavity starts as that tet and
// grows across the base of its worst new tet (never across a fixed face), the best cavity
// whose boundary is a sphere with every cavity point on it is kept; then the point is smoothed
// and the whole kept only if the worst quality rose.
#include <algorithm>
#include <map>
#include <optional>

#include "insertion.hpp"
#include "quality.hpp"
#include "smooth.hpp"

namespace volmesh::improve {

namespace {

constexpr int kMaxCavity = 16;

struct Cone {
  std::vector<Tet> fresh;  // the new point written as kNoIndex
  double quality = kFlatQuality;
  int worst = 0;  // the fresh tet of least quality
};

Tet with_point(Tet t, Index v) {
  std::replace(t.begin(), t.end(), kNoIndex, v);
  return t;
}

// The cone from p over the cavity's boundary, when the cavity is a ball with all its points
// on its boundary and no fixed face inside.
std::optional<Cone> cone(const TetComplex& mesh, const std::vector<Index>& cavity, const Vec3& p) {
  std::map<std::array<Index, 3>, std::array<Index, 3>> faces;  // sorted → outward, once
  std::vector<std::array<Index, 3>> inner;
  for (const Index t : cavity)
    for (const auto& f : kTetFaces) {
      const std::array<Index, 3> loop{mesh.tet(t)[f[0]], mesh.tet(t)[f[1]], mesh.tet(t)[f[2]]};
      std::array<Index, 3> key = loop;
      std::sort(key.begin(), key.end());
      if (!faces.emplace(key, loop).second) {
        faces.erase(key);
        inner.push_back(key);
      }
    }
  for (const auto& f : inner)
    if (mesh.fixed_face(f[0], f[1], f[2])) return std::nullopt;
  std::map<std::array<Index, 2>, int> edges;
  std::vector<Index> rim;
  for (const auto& [key, loop] : faces)
    for (int e = 0; e < 3; ++e) {
      ++edges[{std::min(loop[e], loop[(e + 1) % 3]), std::max(loop[e], loop[(e + 1) % 3])}];
      rim.push_back(loop[e]);
    }
  std::sort(rim.begin(), rim.end());
  rim.erase(std::unique(rim.begin(), rim.end()), rim.end());
  if (std::any_of(edges.begin(), edges.end(), [](const auto& e) { return e.second != 2; }))
    return std::nullopt;
  const auto euler = static_cast<long>(rim.size()) - static_cast<long>(edges.size()) +
                     static_cast<long>(faces.size());
  if (euler != 2) return std::nullopt;
  for (const Index t : cavity)
    for (const Index v : mesh.tet(t))
      if (!std::binary_search(rim.begin(), rim.end(), v)) return std::nullopt;
  Cone c;
  c.quality = std::numeric_limits<double>::infinity();
  for (const auto& [key, f] : faces) {
    c.fresh.push_back({f[0], f[2], f[1], kNoIndex});
    const double q = tet_quality(mesh.point(f[0]), mesh.point(f[2]), mesh.point(f[1]), p);
    if (q < c.quality) {
      c.quality = q;
      c.worst = static_cast<int>(c.fresh.size()) - 1;
    }
  }
  return c;
}

}  // namespace

bool insert_point(TetComplex& mesh, Index t) {
  const Tet& s = mesh.tet(t);
  const Vec3 p = 0.25 * (mesh.point(s[0]) + mesh.point(s[1]) + mesh.point(s[2]) + mesh.point(s[3]));
  std::vector<Index> cavity{t};
  std::optional<Cone> best;
  std::vector<Index> best_cavity;
  std::optional<Cone> current = cone(mesh, cavity, p);
  while (true) {
    if (current && (!best || current->quality > best->quality)) {
      best = current;
      best_cavity = cavity;
    }
    if (!current || static_cast<int>(cavity.size()) >= kMaxCavity) break;
    // Grow across the worst new tet's base.
    const Tet& w = current->fresh[current->worst];
    if (mesh.fixed_face(w[0], w[1], w[2])) break;
    Index next = kNoIndex;
    for (const Index c : cavity)
      if (holds(mesh.tet(c), w[0]) && holds(mesh.tet(c), w[1]) && holds(mesh.tet(c), w[2]))
        next = mesh.across(c, w[0], w[1], w[2]);
    if (next == kNoIndex || mesh.region(next) != mesh.region(t)) break;
    cavity.push_back(next);
    current = cone(mesh, cavity, p);
  }
  if (!best || !(best->quality > 0.0)) return false;
  const double before = mesh.min_quality(best_cavity);
  std::vector<Tet> old;
  for (const Index c : best_cavity) old.push_back(mesh.tet(c));
  const Index v = mesh.add_point(p);
  std::vector<Tet> fresh;
  for (const Tet& f : best->fresh) fresh.push_back(with_point(f, v));
  if (!mesh.all_positive(fresh)) return false;
  const std::vector<Index> slots = mesh.replace(best_cavity, fresh);
  smooth_point(mesh, v);
  if (raises(mesh.min_quality(mesh.star(v)), before)) return true;
  mesh.replace(slots, old);  // undone: the point stays behind with no tet
  return false;
}

}  // namespace volmesh::improve
