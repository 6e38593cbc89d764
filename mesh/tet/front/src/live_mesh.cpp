#include "live_mesh.hpp"

#include <algorithm>

#include "min_sine.hpp"

namespace volmesh::tet::front {

namespace {

std::array<Index, 3> sorted(Index a, Index b, Index c) {
  std::array<Index, 3> f{a, b, c};
  std::sort(f.begin(), f.end());
  return f;
}

bool holds(const Tet& t, Index v) { return std::find(t.begin(), t.end(), v) != t.end(); }

}  // namespace

double quality_of(const std::vector<Vec3>& points, const Tet& t) {
  return min_sine(points[t[0]], points[t[1]], points[t[2]], points[t[3]]);
}

bool even_order(const Tet& stored, Index a, Index b, Index c, Index d) {
  const std::array<Index, 4> wanted{a, b, c, d};
  std::array<int, 4> position{};
  for (int i = 0; i < 4; ++i)
    position[i] = static_cast<int>(std::find(stored.begin(), stored.end(), wanted[i]) - stored.begin());
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) inversions += position[i] > position[j];
  return inversions % 2 == 0;
}

LiveMesh::LiveMesh(TetMesh& m, Index fixed_nodes, const std::vector<std::array<Index, 3>>& kept)
    : m_(m), pinned_(m.points.size(), 0), incident_(m.points.size()), alive_(m.cells.size(), 1),
      quality_(m.cells.size()) {
  std::fill(pinned_.begin(), pinned_.begin() + fixed_nodes, 1);
  for (const auto& f : kept) {
    kept_.insert(sorted(f[0], f[1], f[2]));
    for (const Index v : f) pinned_[v] = 1;
  }
  for (Index t = 0; t < m.num_cells(); ++t) attach(t);
}

bool LiveMesh::kept(Index a, Index b, Index c) const { return kept_.count(sorted(a, b, c)) > 0; }

std::vector<Index> LiveMesh::tets_with(Index a, Index b) const {
  std::vector<Index> out;
  for (const Index t : incident_[a])
    if (holds(m_.cells[t], b)) out.push_back(t);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Index> LiveMesh::tets_with(Index a, Index b, Index c) const {
  std::vector<Index> out;
  for (const Index t : incident_[a])
    if (holds(m_.cells[t], b) && holds(m_.cells[t], c)) out.push_back(t);
  std::sort(out.begin(), out.end());
  return out;
}

void LiveMesh::attach(Index t) {
  for (const Index v : m_.cells[t]) incident_[v].push_back(t);
  quality_[t] = quality_of(m_.points, m_.cells[t]);
  alive_[t] = 1;
}

void LiveMesh::detach(Index t) {
  for (const Index v : m_.cells[t]) std::erase(incident_[v], t);
  alive_[t] = 0;
}

void LiveMesh::replace(const std::vector<Index>& old, const std::vector<Tet>& fresh) {
  const Index region = m_.cell_region[old.front()];
  for (const Index t : old) detach(t);
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    Index slot;
    if (i < old.size()) {
      slot = old[i];
    } else {
      slot = m_.num_cells();
      m_.cells.emplace_back();
      m_.cell_region.push_back(region);
      alive_.push_back(0);
      quality_.push_back(0.0);
    }
    m_.cells[slot] = fresh[i];
    m_.cell_region[slot] = region;
    attach(slot);
  }
}

void LiveMesh::move(Index v, const Vec3& p) {
  m_.points[v] = p;
  for (const Index t : incident_[v]) quality_[t] = quality_of(m_.points, m_.cells[t]);
}

void LiveMesh::compact() {
  Index out = 0;
  for (Index t = 0; t < m_.num_cells(); ++t) {
    if (!alive_[t]) continue;
    m_.cells[out] = m_.cells[t];
    m_.cell_region[out] = m_.cell_region[t];
    ++out;
  }
  m_.cells.resize(out);
  m_.cell_region.resize(out);
  // Nodes left with no tets (collapsed) go; the others keep their order.
  std::vector<Index> renumber(m_.points.size(), kNoIndex);
  Index kept_points = 0;
  for (Index v = 0; v < static_cast<Index>(m_.points.size()); ++v) {
    if (incident_[v].empty()) continue;
    renumber[v] = kept_points;
    m_.points[kept_points] = m_.points[v];
    pinned_[kept_points] = pinned_[v];
    ++kept_points;
  }
  m_.points.resize(kept_points);
  pinned_.resize(kept_points);
  incident_.resize(kept_points);
  for (Tet& c : m_.cells)
    for (Index& v : c) v = renumber[v];
  for (auto& f : m_.boundary_faces)
    for (Index& v : f) v = renumber[v];
  std::set<std::array<Index, 3>> faces;
  for (const auto& f : kept_) faces.insert(sorted(renumber[f[0]], renumber[f[1]], renumber[f[2]]));
  kept_ = std::move(faces);
  alive_.assign(out, 1);
  quality_.resize(out);
  for (Index t = 0; t < out; ++t) quality_[t] = quality_of(m_.points, m_.cells[t]);
  for (auto& list : incident_) list.clear();
  for (Index t = 0; t < out; ++t)
    for (const Index v : m_.cells[t]) incident_[v].push_back(t);
}

}  // namespace volmesh::tet::front
