// Multi-face removal, the inverse of edge removal: a triangulated disk of faces with apex a on
// one side and b on the other (every face's two tets) becomes the fan of tets around the new
// edge ab. The disk grows from one face, greedily by the best result, up to kMaxFaces.
#include <algorithm>
#include <limits>
#include <map>
#include <optional>

#include "quality.hpp"
#include "topology.hpp"

namespace volmesh::improve {

namespace {

constexpr int kMaxFaces = 8;

// A face of the disk, counter-clockwise seen from a, with its tets on a's and b's side.
struct DiskFace {
  std::array<Index, 3> v;
  Index tet_a, tet_b;
};

struct Candidate {
  std::vector<Tet> fresh;
  std::vector<Index> old;
  double quality = kFlatQuality;
};

// The fan replacing the disk, when the disk is one with all its points on its rim and no
// face to remove is fixed.
std::optional<Candidate> fan(const TetComplex& mesh, Index a, Index b,
                             const std::vector<DiskFace>& disk) {
  std::map<std::pair<Index, Index>, int> directed;  // edge → how often, in face order
  for (const DiskFace& f : disk)
    for (int e = 0; e < 3; ++e) ++directed[{f.v[e], f.v[(e + 1) % 3]}];
  std::map<Index, Index> rim;  // rim edges p → q
  for (const auto& [edge, count] : directed) {
    if (count > 1) return std::nullopt;
    const auto [p, q] = edge;
    if (directed.count({q, p})) {
      // An inner edge: its faces with a and b go.
      if (p < q && (mesh.fixed_face(a, p, q) || mesh.fixed_face(b, p, q))) return std::nullopt;
      continue;
    }
    if (!rim.emplace(p, q).second) return std::nullopt;  // a pinched rim
  }
  std::vector<Index> points;
  for (const DiskFace& f : disk) points.insert(points.end(), f.v.begin(), f.v.end());
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() != rim.size() || rim.size() != disk.size() + 2) return std::nullopt;
  // One cycle through every rim point.
  Index p = rim.begin()->first;
  for (std::size_t k = 0; k < rim.size(); ++k) {
    const auto it = rim.find(p);
    if (it == rim.end()) return std::nullopt;
    p = it->second;
    if (p == rim.begin()->first && k + 1 < rim.size()) return std::nullopt;
  }
  Candidate c;
  for (const auto& [from, to] : rim) c.fresh.push_back({from, to, b, a});
  for (const DiskFace& f : disk) {
    c.old.push_back(f.tet_a);
    c.old.push_back(f.tet_b);
  }
  c.quality = mesh.min_quality_of(c.fresh);
  return c;
}

// The disk face across rim edge (p, q) of face f: the tets (a, q, p, w) and (b, q, p, w).
std::optional<DiskFace> neighbour(const TetComplex& mesh, Index a, Index b, const DiskFace& f,
                                  int edge) {
  const Index p = f.v[edge], q = f.v[(edge + 1) % 3];
  const Index tet_a = mesh.across(f.tet_a, a, p, q);
  if (tet_a == kNoIndex) return std::nullopt;
  Index w = kNoIndex;
  for (const Index x : mesh.tet(tet_a))
    if (x != a && x != p && x != q) w = x;
  if (w == b || mesh.fixed_face(p, q, w)) return std::nullopt;
  const std::vector<Index> below = mesh.tets_with(b, p, q);
  for (const Index t : below)
    if (holds(mesh.tet(t), w)) return DiskFace{{q, p, w}, tet_a, t};
  return std::nullopt;
}

}  // namespace

int remove_faces(TetComplex& mesh, Index t, int face) {
  const auto& f = kTetFaces[face];
  const Tet& s = mesh.tet(t);
  // kTetFaces are outward, so reversed they turn counter-clockwise seen from the apex.
  const Index x = s[f[0]], y = s[f[2]], z = s[f[1]];
  if (mesh.fixed_face(x, y, z)) return 0;
  const Index a = s[6 - f[0] - f[1] - f[2]];
  const Index other = mesh.across(t, x, y, z);
  if (other == kNoIndex) return 0;
  Index b = kNoIndex;
  for (const Index v : mesh.tet(other))
    if (!holds(s, v)) b = v;
  // b missing: the tet across has the same corners (a flat mesh can hold such a pair).
  if (b == kNoIndex || !mesh.tets_with(a, b).empty()) return 0;

  std::vector<DiskFace> disk{{{x, y, z}, t, other}};
  std::optional<Candidate> best = fan(mesh, a, b, disk);
  std::size_t best_size = 1;
  while (static_cast<int>(disk.size()) < kMaxFaces) {
    std::optional<Candidate> step;
    DiskFace step_face{};
    // By index and by copy: trying a face appends it to `disk`, which may reallocate.
    for (std::size_t i = 0, faces = disk.size(); i < faces; ++i)
      for (int e = 0; e < 3; ++e) {
        const DiskFace g = disk[i];
        const std::optional<DiskFace> n = neighbour(mesh, a, b, g, e);
        if (!n) continue;
        const bool known = std::any_of(disk.begin(), disk.end(),
                                       [&](const DiskFace& d) { return d.tet_a == n->tet_a; });
        if (known) continue;
        disk.push_back(*n);
        std::optional<Candidate> c = fan(mesh, a, b, disk);
        disk.pop_back();
        if (c && (!step || c->quality > step->quality)) {
          step = std::move(c);
          step_face = *n;
        }
      }
    if (!step) break;
    disk.push_back(step_face);
    if (!best || step->quality > best->quality) {
      best = std::move(step);
      best_size = disk.size();
    }
  }
  if (!best || !raises(best->quality, mesh.min_quality(best->old))) return 0;
  if (!mesh.all_positive(best->fresh)) return 0;
  mesh.replace(best->old, best->fresh);
  return static_cast<int>(best_size);
}

}  // namespace volmesh::improve
