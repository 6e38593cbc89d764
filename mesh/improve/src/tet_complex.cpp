#include "tet_complex.hpp"

#include <algorithm>
#include <limits>
#include <map>

#include "exact.hpp"
#include "quality.hpp"

namespace volmesh::improve {

namespace {

std::array<Index, 3> sorted(Index a, Index b, Index c) {
  std::array<Index, 3> f{a, b, c};
  std::sort(f.begin(), f.end());
  return f;
}

// The faces between two regions, by sorted corners.
std::vector<std::array<Index, 3>> interface_faces(const TetMesh& mesh) {
  std::map<std::array<Index, 3>, Index> seen;
  std::vector<std::array<Index, 3>> out;
  for (Index t = 0; t < mesh.num_cells(); ++t)
    for (const auto& f : kTetFaces) {
      const auto key = sorted(mesh.cells[t][f[0]], mesh.cells[t][f[1]], mesh.cells[t][f[2]]);
      const auto [it, fresh] = seen.emplace(key, mesh.cell_region[t]);
      if (!fresh && it->second != mesh.cell_region[t]) out.push_back(key);
    }
  return out;
}

}  // namespace

bool holds(const Tet& t, Index v) { return std::find(t.begin(), t.end(), v) != t.end(); }

bool even_order(const Tet& stored, Index a, Index b, Index c, Index d) {
  const std::array<Index, 4> wanted{a, b, c, d};
  std::array<int, 4> at{};
  for (int i = 0; i < 4; ++i)
    at[i] = static_cast<int>(std::find(stored.begin(), stored.end(), wanted[i]) - stored.begin());
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) inversions += at[i] > at[j];
  return inversions % 2 == 0;
}

std::array<Index, 2> opposite_edge(const Tet& t, Index a, Index b) {
  std::array<Index, 2> cd{};
  int k = 0;
  for (const Index v : t)
    if (v != a && v != b) cd[k++] = v;
  if (!even_order(t, a, b, cd[0], cd[1])) std::swap(cd[0], cd[1]);
  return cd;
}

std::size_t TetComplex::FaceHash::operator()(const std::array<Index, 3>& f) const {
  // The 64-bit mix of splitmix64 over the three corners.
  std::uint64_t h = 0;
  for (const Index v : f) {
    h ^= static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h = (h ^ (h >> 31)) * 0xbf58476d1ce4e5b9ULL;
  }
  return static_cast<std::size_t>(h);
}

TetComplex::TetComplex(const TetMesh& mesh, const std::vector<Slide>& slides)
    : points_(mesh.points),
      tets_(mesh.cells),
      region_(mesh.cell_region),
      alive_(mesh.cells.size(), 1),
      quality_(mesh.cells.size()),
      star_(mesh.points.size()),
      freedom_(mesh.points.size(), Freedom::Free),
      slides_(mesh.points.size()),
      stamp_(mesh.points.size(), 0),
      boundary_(mesh.boundary_faces),
      boundary_tag_(mesh.boundary_tag) {
  const std::vector<std::array<Index, 3>> interfaces = interface_faces(mesh);
  std::vector<std::array<Index, 3>> fixed = interfaces;
  for (const auto& f : mesh.boundary_faces) fixed.push_back(sorted(f[0], f[1], f[2]));
  fixed_.reserve(fixed.size());
  for (const auto& f : fixed) {
    fixed_.insert(f);
    for (const Index v : f) freedom_[v] = Freedom::Pinned;
  }
  // Only boundary points slide: an interface point stays, like the interface.
  for (const auto& f : mesh.boundary_faces)
    for (const Index v : f)
      if (v < static_cast<Index>(slides.size()) && slides[v].kind != SlideKind::None) {
        freedom_[v] = Freedom::Slides;
        slides_[v] = slides[v];
      }
  for (const auto& f : interfaces)
    for (const Index v : f) freedom_[v] = Freedom::Pinned;
  for (Index f = 0; f < static_cast<Index>(boundary_.size()); ++f)
    boundary_slot_.emplace(sorted(boundary_[f][0], boundary_[f][1], boundary_[f][2]), f);
  for (Index t = 0; t < num_slots(); ++t) attach(t);
}

bool TetComplex::fixed_face(Index a, Index b, Index c) const {
  return fixed_.count(sorted(a, b, c)) > 0;
}

std::vector<Index> TetComplex::tets_with(Index a, Index b) const {
  std::vector<Index> out;
  for (const Index t : star_[a])
    if (holds(tets_[t], b)) out.push_back(t);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Index> TetComplex::tets_with(Index a, Index b, Index c) const {
  std::vector<Index> out;
  for (const Index t : star_[a])
    if (holds(tets_[t], b) && holds(tets_[t], c)) out.push_back(t);
  std::sort(out.begin(), out.end());
  return out;
}

Index TetComplex::across(Index t, Index a, Index b, Index c) const {
  for (const Index s : star_[a])
    if (s != t && holds(tets_[s], b) && holds(tets_[s], c)) return s;
  return kNoIndex;
}

double TetComplex::min_quality(std::span<const Index> tets) const {
  double q = std::numeric_limits<double>::infinity();
  for (const Index t : tets) q = std::min(q, quality_[t]);
  return q;
}

double TetComplex::min_quality_of(std::span<const Tet> tets, double floor) const {
  double q = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < tets.size() && q > floor; ++i)
    q = std::min(q, tet_quality(points_, tets[i]));
  return q;
}

bool TetComplex::all_positive(std::span<const Tet> tets) const {
  return std::all_of(tets.begin(), tets.end(), [&](const Tet& t) {
    return positive(points_[t[0]], points_[t[1]], points_[t[2]], points_[t[3]]);
  });
}

void TetComplex::rename_fixed(Index gone, Index kept) {
  std::vector<std::array<Index, 3>> faces;
  for (const Index t : star_[gone])
    for (const auto& f : kTetFaces) {
      const Tet& c = tets_[t];
      const auto key = sorted(c[f[0]], c[f[1]], c[f[2]]);
      if (std::count(key.begin(), key.end(), gone) > 0 && fixed_.count(key)) faces.push_back(key);
    }
  for (const auto& key : faces) {
    if (fixed_.erase(key) == 0) continue;  // seen from its other tet already
    std::array<Index, 3> renamed = key;
    std::replace(renamed.begin(), renamed.end(), gone, kept);
    const bool degenerate = std::count(key.begin(), key.end(), kept) > 0;
    const auto renamed_key = sorted(renamed[0], renamed[1], renamed[2]);
    if (!degenerate) fixed_.insert(renamed_key);
    const auto slot = boundary_slot_.find(key);
    if (slot == boundary_slot_.end()) continue;
    const Index f = slot->second;
    boundary_slot_.erase(slot);
    if (degenerate) {
      boundary_[f] = {kNoIndex, kNoIndex, kNoIndex};
    } else {
      std::replace(boundary_[f].begin(), boundary_[f].end(), gone, kept);
      boundary_slot_.emplace(renamed_key, f);
    }
  }
}

Index TetComplex::add_point(const Vec3& p) {
  points_.push_back(p);
  star_.emplace_back();
  freedom_.push_back(Freedom::Free);
  slides_.emplace_back();
  stamp_.push_back(++clock_);
  return num_points() - 1;
}

void TetComplex::attach(Index t) {
  for (const Index v : tets_[t]) star_[v].push_back(t);
  quality_[t] = tet_quality(points_, tets_[t]);
  alive_[t] = 1;
}

void TetComplex::detach(Index t) {
  for (const Index v : tets_[t]) std::erase(star_[v], t);
  alive_[t] = 0;
}

std::vector<Index> TetComplex::replace(std::span<const Index> old, std::span<const Tet> fresh) {
  const Index region = region_[old.front()];
  ++clock_;
  for (const Index t : old) {
    touch(tets_[t]);
    detach(t);
  }
  std::vector<Index> slots;
  for (const Tet& t : fresh) {
    slots.push_back(num_slots());
    tets_.push_back(t);
    region_.push_back(region);
    alive_.push_back(0);
    quality_.push_back(0.0);
    attach(slots.back());
    touch(t);
  }
  return slots;
}

void TetComplex::move(Index v, const Vec3& p) {
  points_[v] = p;
  ++clock_;
  for (const Index t : star_[v]) {
    quality_[t] = tet_quality(points_, tets_[t]);
    touch(tets_[t]);
  }
}

double TetComplex::worst_quality() const {
  double q = std::numeric_limits<double>::infinity();
  for (Index t = 0; t < num_slots(); ++t)
    if (alive_[t]) q = std::min(q, quality_[t]);
  return q;
}

void TetComplex::write_to(TetMesh& mesh, bool keep_numbers) const {
  std::vector<Index> renumber(points_.size(), kNoIndex);
  mesh.points.clear();
  for (Index v = 0; v < num_points(); ++v)
    if (keep_numbers || !star_[v].empty()) {
      renumber[v] = static_cast<Index>(mesh.points.size());
      mesh.points.push_back(points_[v]);
    }
  mesh.cells.clear();
  mesh.cell_region.clear();
  for (Index t = 0; t < num_slots(); ++t) {
    if (!alive_[t]) continue;
    Tet c;
    for (int k = 0; k < 4; ++k) c[k] = renumber[tets_[t][k]];
    mesh.cells.push_back(c);
    mesh.cell_region.push_back(region_[t]);
  }
  mesh.boundary_faces.clear();
  mesh.boundary_tag.clear();
  for (std::size_t f = 0; f < boundary_.size(); ++f) {
    if (boundary_[f][0] == kNoIndex) continue;
    mesh.boundary_faces.push_back(
        {renumber[boundary_[f][0]], renumber[boundary_[f][1]], renumber[boundary_[f][2]]});
    if (f < boundary_tag_.size()) mesh.boundary_tag.push_back(boundary_tag_[f]);
  }
}

}  // namespace volmesh::improve
