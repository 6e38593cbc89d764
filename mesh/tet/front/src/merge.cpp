#include "merge.hpp"

#include <algorithm>

#include "predicates.hpp"
#include "volmesh/core/element_mesh.hpp"

namespace volmesh::tet::front {

namespace {

Edge edge_key(Index a, Index b) { return a < b ? Edge{a, b} : Edge{b, a}; }

bool same_orientation(const Tri& a, const Tri& b) {
  for (int r = 0; r < 3; ++r)
    if (a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3]) return true;
  return false;
}

std::vector<Tri> oriented_as(const Tri& face, const Tri& stored, const std::vector<Tri>& pieces) {
  if (same_orientation(face, stored)) return pieces;
  std::vector<Tri> out;
  for (const Tri& p : pieces) out.push_back(reversed(p));
  return out;
}

// The points inside edge a -> b, in order from a.
std::vector<Index> points_on(const CavitySplit& split, Index a, Index b) {
  const auto it = split.edge_points.find(edge_key(a, b));
  if (it == split.edge_points.end()) return {};
  std::vector<Index> on = it->second;
  if (a > b) std::reverse(on.begin(), on.end());
  return on;
}

bool touches(const CavitySplit& split, const Tri& f) {
  if (split.faces.count(corners_of(f))) return true;
  for (int i = 0; i < 3; ++i)
    if (split.edge_points.count(edge_key(f[i], f[(i + 1) % 3]))) return true;
  return false;
}

// The pieces of face f (oriented as f) under the split.
std::vector<Tri> pieces_of(const CavitySplit& split, const Tri& f) {
  const auto it = split.faces.find(corners_of(f));
  if (it != split.faces.end()) return oriented_as(f, it->second.first, it->second.second);
  std::vector<Tri> out;
  split_canonically(f, {points_on(split, f[0], f[1]), points_on(split, f[1], f[2]),
                        points_on(split, f[2], f[0])},
                    out);
  return out;
}

}  // namespace

Tri corners_of(const Tri& t) {
  Tri s = t;
  std::sort(s.begin(), s.end());
  return s;
}

Tri reversed(const Tri& t) { return {t[0], t[2], t[1]}; }

void FaceSplits::record(const Tri& face, const std::vector<Tri>& pieces) {
  by_corners_[corners_of(face)] = {face, pieces};
}

void FaceSplits::resolve(const Tri& face, std::vector<Tri>& out) const {
  const auto it = by_corners_.find(corners_of(face));
  if (it == by_corners_.end()) {
    out.push_back(face);
    return;
  }
  for (const Tri& p : oriented_as(face, it->second.first, it->second.second)) resolve(p, out);
}

void split_canonically(const Tri& t, const std::array<std::vector<Index>, 3>& on_edge,
                       std::vector<Tri>& out) {
  int edge = -1;
  std::size_t at = 0;
  for (int i = 0; i < 3; ++i)
    for (std::size_t k = 0; k < on_edge[i].size(); ++k)
      if (edge < 0 || on_edge[i][k] < on_edge[edge][at]) {
        edge = i;
        at = k;
      }
  if (edge < 0) {
    out.push_back(t);
    return;
  }
  const int next = (edge + 1) % 3, opposite = (edge + 2) % 3;
  const std::vector<Index>& cut = on_edge[edge];
  const Index p = cut[at];
  split_canonically({t[edge], p, t[opposite]},
                    {std::vector<Index>(cut.begin(), cut.begin() + static_cast<long>(at)), {},
                     on_edge[opposite]},
                    out);
  split_canonically({p, t[next], t[opposite]},
                    {std::vector<Index>(cut.begin() + static_cast<long>(at) + 1, cut.end()),
                     on_edge[next], {}},
                    out);
}

bool refine_around(std::vector<Vec3>& points, std::vector<Tet>& cells, std::vector<Index>& labels,
                   const CavitySplit& split, const std::vector<Tri>& loose, FaceSplits& splits,
                   Refinement& refinement) {
  std::vector<Vec3> centroids;
  std::vector<Tet> out_cells;
  std::vector<Index> out_labels;
  std::vector<std::pair<Tri, std::vector<Tri>>> cut;
  const auto at = [&](Index i) -> const Vec3& {
    return i < static_cast<Index>(points.size()) ? points[i] : centroids[i - points.size()];
  };
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const Tet& t = cells[c];
    bool hit = false;
    for (const auto& e : kTetEdges) hit = hit || split.edge_points.count(edge_key(t[e[0]], t[e[1]]));
    for (const auto& f : kTetFaces) hit = hit || split.faces.count(corners_of({t[f[0]], t[f[1]], t[f[2]]}));
    if (!hit) {
      out_cells.push_back(t);
      out_labels.push_back(labels[c]);
      continue;
    }
    const Index apex = static_cast<Index>(points.size() + centroids.size());
    centroids.push_back((points[t[0]] + points[t[1]] + points[t[2]] + points[t[3]]) / 4.0);
    for (const auto& f : kTetFaces) {
      const Tri face{t[f[0]], t[f[2]], t[f[1]]};  // facing into the tet, towards its centroid
      const std::vector<Tri> pieces = pieces_of(split, face);
      if (pieces.size() > 1) cut.emplace_back(face, pieces);
      for (const Tri& p : pieces) {
        if (!positive(at(p[0]), at(p[1]), at(p[2]), at(apex))) return false;
        out_cells.push_back({p[0], p[1], p[2], apex});
        out_labels.push_back(labels[c]);
      }
    }
    ++refinement.tets;
  }
  for (const Tri& f : loose)
    if (touches(split, f)) cut.emplace_back(f, pieces_of(split, f));
  for (const auto& [face, pieces] : cut)
    if (pieces.size() > 1) splits.record(face, pieces);
  refinement.centroids += static_cast<long long>(centroids.size());
  points.insert(points.end(), centroids.begin(), centroids.end());
  cells = std::move(out_cells);
  labels = std::move(out_labels);
  return true;
}

}  // namespace volmesh::tet::front
