// Thin and curved parts refined within a growth bound (refine_thin.hpp): the field's measures per
// boundary hex, then the marks taken seed by seed, each closed locally and undone when over the
// bound.
#include "volmesh/hexdc/refine_thin.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <tbb/parallel_for.h>

#include "refine_templates.hpp"
#include "refine_thin_measure.hpp"

namespace volmesh {
namespace {

// A hex whose shortest edge is below this fraction of its mean edge is collapsed: the
// optimiser's edge floor, which its children could not keep.
constexpr double kCollapsedEdge = 1e-3;
// Quads a boundary quad becomes by its number of marked corners (refine.hpp): 0, 1, 2 on one
// edge, 4 (3 cannot occur once closed).
constexpr std::array<Index, 5> kQuadsByMarks{1, 3, 7, 0, 9};
// A node's mark: none, kept from an earlier seed, or added by the seed being tried.
constexpr char kUnmarked = 0, kKept = 1, kAdded = 2;

double mean_edge(const HexMesh& mesh, const std::array<Index, 8>& cell, double* shortest) {
  double sum = 0.0;
  *shortest = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : kHexEdges) {
    const double length = (mesh.points[static_cast<std::size_t>(cell[static_cast<std::size_t>(a)])] -
                           mesh.points[static_cast<std::size_t>(cell[static_cast<std::size_t>(b)])])
                              .norm();
    sum += length;
    *shortest = std::min(*shortest, length);
  }
  return sum / static_cast<double>(kHexEdges.size());
}

// kHexFaces' pairs of opposite faces.
constexpr std::array<std::array<std::size_t, 2>, 3> kOppositeFaces{{{0, 1}, {2, 4}, {3, 5}}};

using QuadKey = std::array<Index, 4>;

QuadKey sorted_quad(QuadKey q) {
  std::sort(q.begin(), q.end());
  return q;
}

// Per hex: two opposite faces on the boundary (one hex across), its width (kNoWidth unless
// thin), its normals' spread, whether an edge is collapsed.
struct HexMeasures {
  std::vector<char> across;
  std::vector<double> width, spread;
  std::vector<char> collapsed;
};

std::vector<char> one_hex_across(const HexMesh& mesh) {
  std::vector<QuadKey> boundary;
  for (const auto& quad : mesh.boundary_faces) boundary.push_back(sorted_quad(quad));
  std::sort(boundary.begin(), boundary.end());
  const auto on_boundary = [&](const std::array<Index, 8>& cell, std::size_t f) {
    const auto& face = kHexFaces[f];
    QuadKey q;
    for (std::size_t i = 0; i < 4; ++i) q[i] = cell[static_cast<std::size_t>(face[i])];
    return std::binary_search(boundary.begin(), boundary.end(), sorted_quad(q));
  };
  std::vector<char> across(mesh.cells.size(), 0);
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    for (const auto& [a, b] : kOppositeFaces)
      if (on_boundary(mesh.cells[h], a) && on_boundary(mesh.cells[h], b)) across[h] = 1;
  return across;
}

HexMeasures measure(const HexMesh& mesh, const VoxelGrid& field) {
  const auto n = static_cast<std::size_t>(mesh.num_cells());
  HexMeasures m{one_hex_across(mesh), std::vector<double>(n, hexdc_detail::kNoWidth),
                std::vector<double>(n, 0.0), std::vector<char>(n, 0)};
  std::vector<char> on_boundary(mesh.points.size(), 0);
  for (const auto& quad : mesh.boundary_faces)
    for (const Index v : quad) on_boundary[static_cast<std::size_t>(v)] = 1;
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t h) {
    const auto& cell = mesh.cells[h];
    double shortest = 0.0;
    const double edge = mean_edge(mesh, cell, &shortest);
    m.collapsed[h] = shortest < kCollapsedEdge * edge ? 1 : 0;
    if (std::none_of(cell.begin(), cell.end(),
                     [&](Index v) { return on_boundary[static_cast<std::size_t>(v)] != 0; }))
      return;
    std::array<Vec3, 8> corners;
    for (std::size_t c = 0; c < 8; ++c) corners[c] = mesh.points[static_cast<std::size_t>(cell[c])];
    const hexdc_detail::SampleBox box = hexdc_detail::sample_box(field, corners);
    const hexdc_detail::SurfaceMeasures s = hexdc_detail::surface_measures(field, box, kThinCells * edge);
    m.width[h] = s.width;
    m.spread[h] = s.spread_deg;
  });
  return m;
}

// Node marks grown seed by seed, each closed over the hexes it reaches and undone when the
// refined mesh would pass the bound; tracks the refined mesh's hexes plus boundary quads.
class MarkBudget {
 public:
  MarkBudget(const HexMesh& mesh, const std::vector<char>& collapsed, Index limit)
      : mesh_(mesh), collapsed_(collapsed), limit_(limit), marked_(mesh.points.size(), 0),
        node_hexes_(mesh.points.size()), node_quads_(mesh.points.size()) {
    for (std::size_t h = 0; h < mesh.cells.size(); ++h)
      for (const Index v : mesh.cells[h]) node_hexes_[static_cast<std::size_t>(v)].push_back(h);
    for (std::size_t q = 0; q < mesh.boundary_faces.size(); ++q)
      for (const Index v : mesh.boundary_faces[q]) node_quads_[static_cast<std::size_t>(v)].push_back(q);
    total_ = mesh.num_cells() + static_cast<Index>(mesh.boundary_faces.size());
  }

  enum class Outcome { taken, over_bound, collapsed };

  // Marks the corners of hex h and closes the marks; undone unless the result fits.
  Outcome mark_hex(std::size_t h) {
    added_.clear();
    std::vector<std::size_t> work;
    const auto mark = [&](Index v) {
      auto& m = marked_[static_cast<std::size_t>(v)];
      if (m != kUnmarked) return;
      m = kAdded;
      added_.push_back(v);
      const auto& around = node_hexes_[static_cast<std::size_t>(v)];
      work.insert(work.end(), around.begin(), around.end());
    };
    for (const Index v : mesh_.cells[h]) mark(v);
    while (!work.empty()) {
      const auto& cell = mesh_.cells[work.back()];
      work.pop_back();
      const unsigned mask = hexdc_detail::corner_mask(cell, marked_);
      const unsigned closed = hexdc_detail::closed_mask(mask);
      for (std::size_t c = 0; c < 8; ++c)
        if (((closed & ~mask) >> c) & 1u) mark(cell[c]);
    }
    const auto [delta, splits_collapsed] = change();
    const bool fits = !splits_collapsed && total_ + delta <= limit_;
    for (const Index v : added_) marked_[static_cast<std::size_t>(v)] = fits ? kKept : kUnmarked;
    if (!fits) return splits_collapsed ? Outcome::collapsed : Outcome::over_bound;
    total_ += delta;
    return Outcome::taken;
  }

  bool all_marked(std::size_t h) const {
    return std::all_of(mesh_.cells[h].begin(), mesh_.cells[h].end(),
                       [&](Index v) { return marked_[static_cast<std::size_t>(v)] != 0; });
  }
  const std::vector<char>& marks() const { return marked_; }

 private:
  // The change in hexes plus boundary quads the marks just added make, and whether they split
  // a collapsed hex.
  std::pair<Index, bool> change() {
    std::vector<std::size_t> hexes, quads;
    for (const Index v : added_) {
      const auto& h = node_hexes_[static_cast<std::size_t>(v)];
      const auto& q = node_quads_[static_cast<std::size_t>(v)];
      hexes.insert(hexes.end(), h.begin(), h.end());
      quads.insert(quads.end(), q.begin(), q.end());
    }
    for (auto* list : {&hexes, &quads}) {
      std::sort(list->begin(), list->end());
      list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    Index delta = 0;
    bool splits_collapsed = false;
    for (const std::size_t h : hexes) {
      delta += hex_count(mask_of(mesh_.cells[h], true)) - hex_count(mask_of(mesh_.cells[h], false));
      splits_collapsed = splits_collapsed || collapsed_[h] != 0;
    }
    for (const std::size_t q : quads) delta += quad_count(q, true) - quad_count(q, false);
    return {delta, splits_collapsed};
  }

  bool counts(Index v, bool with_added) const {
    const char m = marked_[static_cast<std::size_t>(v)];
    return m == kKept || (with_added && m == kAdded);
  }

  // A hex's corner mask with the marks as they are, or without those just added (both closed).
  unsigned mask_of(const std::array<Index, 8>& cell, bool with_added) const {
    unsigned mask = 0;
    for (std::size_t c = 0; c < 8; ++c)
      if (counts(cell[c], with_added)) mask |= 1u << c;
    return mask;
  }

  static Index hex_count(unsigned closed) {
    return static_cast<Index>(hexdc_detail::template_hexes(closed).size());
  }

  // Boundary quad q's pieces with the marks as they are, or without those just added.
  Index quad_count(std::size_t q, bool with_added) const {
    std::size_t marks = 0;
    for (const Index v : mesh_.boundary_faces[q])
      if (counts(v, with_added)) ++marks;
    return kQuadsByMarks[marks];
  }

  const HexMesh& mesh_;
  const std::vector<char>& collapsed_;
  Index limit_, total_ = 0;
  std::vector<char> marked_;
  std::vector<std::vector<std::size_t>> node_hexes_, node_quads_;
  std::vector<Index> added_;
};

enum class Kind : std::uint8_t { across, thin, curved };

// Whether a point of `points` lies in hex h's bounding box grown by its mean edge.
bool near_any(const HexMesh& mesh, std::size_t h, const std::vector<Vec3>& points) {
  if (points.empty()) return false;
  Eigen::AlignedBox3d box;
  for (const Index v : mesh.cells[h]) box.extend(mesh.points[static_cast<std::size_t>(v)]);
  double shortest = 0.0;
  const double edge = mean_edge(mesh, mesh.cells[h], &shortest);
  box.min().array() -= edge;
  box.max().array() += edge;
  return std::any_of(points.begin(), points.end(), [&](const Vec3& p) { return box.contains(p); });
}

}  // namespace

ThinRefineStats refine_thin_parts(HexMesh& mesh, const VoxelGrid& field,
                                  const std::vector<Vec3>& first, double max_growth) {
  ThinRefineStats stats;
  stats.hexes_before = mesh.num_cells();
  stats.boundary_quads_before = static_cast<Index>(mesh.boundary_faces.size());
  const HexMeasures m = measure(mesh, field);

  // Seeds near `first` before the others, then by kind (one hex across, thin, curved), then by
  // measure; ties in hex order.
  std::vector<std::tuple<bool, Kind, double, std::size_t>> seeds;
  for (std::size_t h = 0; h < m.width.size(); ++h) {
    const bool later = !near_any(mesh, h, first);
    if (m.across[h] != 0)
      seeds.emplace_back(later, Kind::across, m.width[h], h);
    else if (m.width[h] != hexdc_detail::kNoWidth)
      seeds.emplace_back(later, Kind::thin, m.width[h], h);
    else if (m.spread[h] > kCurvedAngleDeg)
      seeds.emplace_back(later, Kind::curved, -m.spread[h], h);
  }
  std::sort(seeds.begin(), seeds.end());
  const auto limit = static_cast<Index>(
      max_growth * static_cast<double>(stats.hexes_before + stats.boundary_quads_before));
  MarkBudget budget(mesh, m.collapsed, limit);
  for (const auto& [later, kind, order, h] : seeds) {
    const bool thin = kind != Kind::curved;
    (thin ? stats.thin_hexes : stats.curved_hexes) += 1;
    const auto outcome =
        budget.all_marked(h) ? MarkBudget::Outcome::taken : budget.mark_hex(h);
    switch (outcome) {
      case MarkBudget::Outcome::taken:
        (thin ? stats.thin_refined : stats.curved_refined) += 1;
        break;
      case MarkBudget::Outcome::collapsed:
        ++stats.skipped_collapsed;
        break;
      case MarkBudget::Outcome::over_bound:
        break;
    }
  }
  stats.refinement = refine_hexes(mesh, budget.marks());
  stats.hexes_after = mesh.num_cells();
  stats.boundary_quads_after = static_cast<Index>(mesh.boundary_faces.size());
  return stats;
}

}  // namespace volmesh
