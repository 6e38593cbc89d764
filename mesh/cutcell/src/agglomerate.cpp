#include "agglomerate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <utility>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>

#include "volmesh/core/geometry.hpp"
#include "cell_split.hpp"
#include "volmesh/geometry/polygon_split.hpp"
#include "volmesh/quality/face_metrics.hpp"

namespace volmesh::cutcell {
namespace {

// A candidate merging more cells ranks worse by this fraction per cell beyond two, so that
// of two nearly equal candidates the smaller merge wins.
constexpr double kExtraCellPenalty = 0.01;
// Candidate groups scored per task.
constexpr std::size_t kGroupsPerTask = 8;

class Agglomerator {
 public:
  Agglomerator(PolyMesh& mesh, std::vector<double>& size, const AgglomerationOptions& options)
      : mesh_(mesh), size_(size), options_(options) {
    const CellFaces cf = build_cell_faces(mesh);
    face_.resize(mesh.num_faces());
    tbb::parallel_for(Index{0}, mesh.num_faces(), [&](Index f) { face_[f] = face_geometry(mesh, f); });
    faces_of_.resize(mesh.num_cells());
    cell_.resize(mesh.num_cells());
    for (Index c = 0; c < mesh.num_cells(); ++c) faces_of_[c].assign(cf.of(c).begin(), cf.of(c).end());
    tbb::parallel_for(Index{0}, mesh.num_cells(),
                      [&](Index c) { cell_[c] = union_geometry(std::span<const Index>(&c, 1)); });
    face_alive_.assign(mesh.num_faces(), 1);
    joined_loop_.assign(mesh.num_faces(), kNoIndex);
    cell_alive_.assign(mesh.num_cells(), 1);
    limits_ = options.limits;
  }
  AgglomerationStats run();
  // The faces' geometry, of the rebuilt mesh once run() has rebuilt it.
  std::vector<FaceGeometry> take_face_geometry() { return std::move(face_); }

 private:
  // checkMesh's verdict on a face (face_metrics.hpp): above 1 where it would complain.
  double score(const FaceGeometry& g, std::span<const Index> loop, const Vec3& owner,
               const Vec3* neighbour) const {
    return checkmesh_badness(g, mesh_.points, loop, owner, neighbour, limits_);
  }
  double score(Index f, const Vec3& owner, const Vec3* neighbour) const {
    return score(face_[f], loop(f), owner, neighbour);
  }
  // Face f's loop: the mesh's, or the polygon join_faces made of it.
  std::span<const Index> loop(Index f) const {
    return joined_loop_[f] == kNoIndex ? mesh_.face(f) : std::span<const Index>(joined_loops_[joined_loop_[f]]);
  }
  bool join_faces(Index f);
  double face_score(Index f) const {
    const Index n = mesh_.neighbour[f];
    return score(f, cell_[mesh_.owner[f]].centre, n == kNoIndex ? nullptr : &cell_[n].centre);
  }
  // scores in run() only pick out the faces beyond the limits and rank those: a face surely
  // within them scores 0 there without the vertex loop (they are most faces).
  double screened_score(Index f) const {
    const Index n = mesh_.neighbour[f];
    const Vec3* nc = n == kNoIndex ? nullptr : &cell_[n].centre;
    return surely_within_checkmesh_limits(face_[f], cell_[mesh_.owner[f]].centre, nc, limits_) ? 0.0 : face_score(f);
  }
  double worst_of(Index c) const {
    double w = 0.0;
    for (Index f : faces_of_[c]) w = std::max(w, face_score(f));
    return w;
  }
  Index other_side(Index f, Index c) const { return mesh_.owner[f] == c ? mesh_.neighbour[f] : mesh_.owner[f]; }
  CellGeometry union_geometry(std::span<const Index> cells) const;
  // Cells to merge into one: up to three, the unused slots kNoIndex.
  using Group = std::array<Index, 3>;
  static std::span<const Index> cells_of(const Group& g) {
    return {g.data(), static_cast<std::size_t>(g[1] == kNoIndex ? 1 : g[2] == kNoIndex ? 2 : 3)};
  }
  double merged_worst(std::span<const Group> groups, double cutoff) const;
  std::vector<Index> region_neighbours(Index c) const;
  std::vector<Group> groups_around(Index x) const;
  void merge_groups(std::span<const Group> groups);
  bool merge_best(const std::vector<std::vector<Group>>& candidates, bool tiny);
  bool try_merge(Index x, bool tiny);
  void merge(Index x, Index y);
  void rebuild();

  PolyMesh& mesh_;
  std::vector<double>& size_;
  const AgglomerationOptions& options_;
  CheckMeshLimits limits_;
  std::vector<FaceGeometry> face_;
  std::vector<CellGeometry> cell_;
  std::vector<std::vector<Index>> faces_of_;
  std::vector<char> face_alive_, cell_alive_;
  // The faces join_faces grew: per face an index into joined_loops_, kNoIndex for the rest
  // (the other loops stay in the mesh, not copied: there are few joined faces).
  std::vector<Index> joined_loop_;
  std::vector<std::vector<Index>> joined_loops_;
  std::vector<Index> changed_;  // cells whose centre or faces changed since the last round
};

// Volume and centre of the union of the cells as checkMesh computes them.
CellGeometry Agglomerator::union_geometry(std::span<const Index> cells) const {
  const auto inside = [&cells](Index c) { return std::find(cells.begin(), cells.end(), c) != cells.end(); };
  return checkmesh_cell_geometry([&](const auto& visit) {
    for (const Index c : cells)
      for (Index f : faces_of_[c])
        if (const Index o = other_side(f, c); o == kNoIndex || !inside(o))
          visit(mesh_.owner[f] == c ? face_[f].area_vector : Vec3(-face_[f].area_vector), face_[f].centre);
  });
}

// The worst score of the faces around the groups of cells (disjoint), each group merged into
// one cell with the centre union_geometry gives it; once it reaches `cutoff`, any score from
// there up.
double Agglomerator::merged_worst(std::span<const Group> groups, double cutoff) const {
  std::vector<std::pair<Index, Vec3>> centre;
  for (const Group& g : groups) {
    const Vec3 c = union_geometry(cells_of(g)).centre;
    for (Index x : cells_of(g)) centre.emplace_back(x, c);
  }
  const auto centre_of = [&](Index c) -> const Vec3& {
    for (const auto& [x, p] : centre)
      if (x == c) return p;
    return cell_[c].centre;
  };
  const auto group_of = [&](Index c) {
    for (std::size_t k = 0; k < groups.size(); ++k)
      for (Index x : cells_of(groups[k]))
        if (x == c) return static_cast<int>(k);
    return -1;
  };
  double worst = 0.0;
  for (std::size_t k = 0; k < groups.size(); ++k)
    for (const Index c : cells_of(groups[k]))
      for (Index f : faces_of_[c]) {
        const Index o = other_side(f, c);
        if (o != kNoIndex && group_of(o) == static_cast<int>(k)) continue;
        const Index owner = mesh_.owner[f];
        worst = std::max(worst, o == kNoIndex ? score(f, centre_of(c), nullptr)
                                              : score(f, centre_of(owner), &centre_of(mesh_.neighbour[f])));
        if (worst >= cutoff) return worst;
      }
  return worst;
}

// The neighbours of c in its region.
std::vector<Index> Agglomerator::region_neighbours(Index c) const {
  std::vector<Index> out;
  for (Index f : faces_of_[c]) {
    const Index y = other_side(f, c);
    if (y != kNoIndex && mesh_.cell_region[y] == mesh_.cell_region[c] &&
        std::find(out.begin(), out.end(), y) == out.end())
      out.push_back(y);
  }
  return out;
}

// x with a neighbour of its region, or with two (both neighbours of x, or one through the
// other): a thin piece wrapped around a cell of another region may need two to pull its
// centre back.
std::vector<Agglomerator::Group> Agglomerator::groups_around(Index x) const {
  const std::vector<Index> near = region_neighbours(x);
  std::vector<Group> out;
  for (std::size_t i = 0; i < near.size(); ++i) {
    out.push_back({x, near[i], kNoIndex});
    for (std::size_t j = i + 1; j < near.size(); ++j) out.push_back({x, near[i], near[j]});
    for (Index z : region_neighbours(near[i]))
      if (z != x && std::find(near.begin(), near.end(), z) == near.end()) out.push_back({x, near[i], z});
  }
  return out;
}

// Merges the groups, each into its largest cell.
void Agglomerator::merge_groups(std::span<const Group> groups) {
  for (const Group& g : groups) {
    Index into = g[0];
    for (Index c : cells_of(g))
      if (cell_[c].volume > cell_[into].volume) into = c;
    for (Index c : cells_of(g))
      if (c != into) merge(c, into);
    cell_[into] = union_geometry(std::span<const Index>(&into, 1));
    changed_.push_back(into);
  }
}

// The best of the candidate merges when it is better than the cells were (a tiny cell: not
// beyond the limits, or no worse). A second neighbour only where one does not do.
bool Agglomerator::merge_best(const std::vector<std::vector<Group>>& candidates, bool tiny) {
  // A cell has about a hundred candidate groups: they are scored in parallel. The first
  // one's rank bounds the winner's: the others stop scoring once they cannot beat it.
  if (candidates.empty()) return false;
  const auto weight = [](const std::vector<Group>& groups) {
    std::size_t cells = 0;
    for (const Group& g : groups) cells += cells_of(g).size();
    return 1.0 + kExtraCellPenalty * static_cast<double>(cells - 2);
  };
  std::vector<double> worst(candidates.size());
  worst[0] = merged_worst(candidates[0], std::numeric_limits<double>::infinity());
  const double bound = worst[0] * weight(candidates[0]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(1, candidates.size(), kGroupsPerTask), [&](const auto& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k)
      worst[k] = merged_worst(candidates[k], bound / weight(candidates[k]));
  });
  const std::vector<Group>* best = nullptr;
  double best_rank = std::numeric_limits<double>::infinity(), best_worst = best_rank;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    if (const double rank = worst[k] * weight(candidates[k]); rank < best_rank) {
      best_rank = rank;
      best_worst = worst[k];
      best = &candidates[k];
    }
  }
  if (!best) return false;
  double before = 0.0;
  for (const Group& g : *best)
    for (Index c : cells_of(g)) before = std::max(before, worst_of(c));
  if (!(best_worst < before || (tiny && best_worst <= 1.0))) return false;
  merge_groups(*best);
  return true;
}

bool Agglomerator::try_merge(Index x, bool tiny) {
  std::vector<std::vector<Group>> candidates;
  for (const Group& g : groups_around(x)) candidates.push_back({g});
  return merge_best(candidates, tiny);
}

// A face beyond the limits between two cells joined with a face beside it between the same
// two cells (sharing one edge) into one polygon, while that lowers its score and the
// polygon does not fold over itself: a sliver triangle's normal is all but arbitrary, the
// polygon's is that of the patch.
bool Agglomerator::join_faces(Index f) {
  const Index owner = mesh_.owner[f], neighbour = mesh_.neighbour[f];
  bool joined = false;
  // A join takes a face from each cell; a polyhedron keeps at least four.
  const auto can_lose_a_face = [this](Index c) { return c == kNoIndex || faces_of_[c].size() > 4; };
  for (;;) {
    if (!can_lose_a_face(owner) || !can_lose_a_face(neighbour)) return joined;
    const Vec3* nc = neighbour == kNoIndex ? nullptr : &cell_[neighbour].centre;
    double best = face_score(f);
    if (best <= 1.0) return joined;
    Index best_g = kNoIndex;
    std::vector<Index> best_loop;
    FaceGeometry best_geometry{};
    for (Index g : faces_of_[owner]) {
      if (g == f || other_side(g, owner) != neighbour || mesh_.face_tag[g] != mesh_.face_tag[f]) continue;
      std::vector<Index> other(loop(g).begin(), loop(g).end());
      if (mesh_.owner[g] != owner) std::reverse(other.begin(), other.end());
      std::vector<Index> merged = merge_along_edge({loop(f).begin(), loop(f).end()}, other);
      // A polygon folded over itself would fold the cells on it.
      if (merged.empty() || split_polygon(mesh_.points, merged).folded) continue;
      const FaceGeometry geometry = polygon_geometry(mesh_.points, merged);
      if (const double w = score(geometry, merged, cell_[owner].centre, nc); w < best) {
        best = w;
        best_g = g;
        best_loop = std::move(merged);
        best_geometry = geometry;
      }
    }
    if (best_g == kNoIndex) return joined;
    if (joined_loop_[f] == kNoIndex) {
      joined_loop_[f] = static_cast<Index>(joined_loops_.size());
      joined_loops_.emplace_back();
    }
    joined_loops_[joined_loop_[f]] = std::move(best_loop);
    face_[f] = best_geometry;
    face_alive_[best_g] = 0;
    for (const Index c : {owner, neighbour})
      if (c != kNoIndex) {
        std::erase(faces_of_[c], best_g);
        cell_[c] = union_geometry(std::span<const Index>(&c, 1));
        changed_.push_back(c);
      }
    joined = true;
  }
}

// y absorbs x: their shared faces go, x's other faces turn to y.
void Agglomerator::merge(Index x, Index y) {
  std::vector<Index>& into = faces_of_[y];
  for (Index f : faces_of_[x]) {
    if (other_side(f, x) == y) {
      face_alive_[f] = 0;
      std::erase(into, f);
      continue;
    }
    (mesh_.owner[f] == x ? mesh_.owner[f] : mesh_.neighbour[f]) = y;
    into.push_back(f);
  }
  faces_of_[x].clear();
  size_[y] = std::max(size_[x], size_[y]);
  cell_alive_[x] = 0;
}

// The mesh without the merged cells, the removed faces and the points no face uses.
void Agglomerator::rebuild() {
  std::vector<Index> cell_id(mesh_.num_cells(), kNoIndex);
  PolyMesh out;
  std::vector<double> sizes;
  for (Index c = 0; c < mesh_.num_cells(); ++c)
    if (cell_alive_[c]) {
      cell_id[c] = static_cast<Index>(out.cell_region.size());
      out.cell_region.push_back(mesh_.cell_region[c]);
      sizes.push_back(size_[c]);
    }
  std::vector<Index> point_id(mesh_.num_points(), kNoIndex);
  std::size_t faces = 0, corners = 0;
  for (Index f = 0; f < mesh_.num_faces(); ++f)
    if (face_alive_[f]) {
      ++faces;
      corners += loop(f).size();
      for (Index v : loop(f)) point_id[v] = 0;
    }
  out.reserve_faces(faces, corners);
  out.points.reserve(mesh_.points.size());
  for (Index v = 0; v < mesh_.num_points(); ++v)
    if (point_id[v] == 0) {
      point_id[v] = static_cast<Index>(out.points.size());
      out.points.push_back(mesh_.points[v]);
    }
  out.tag_names = mesh_.tag_names;
  std::vector<Index> renumbered;
  std::vector<FaceGeometry> geometry;
  geometry.reserve(faces);
  for (Index f = 0; f < mesh_.num_faces(); ++f) {
    if (!face_alive_[f]) continue;
    renumbered.clear();
    for (Index v : loop(f)) renumbered.push_back(point_id[v]);
    const Index n = mesh_.neighbour[f];
    out.add_face(renumbered, cell_id[mesh_.owner[f]], n == kNoIndex ? kNoIndex : cell_id[n], mesh_.face_tag[f]);
    geometry.push_back(face_[f]);
  }
  mesh_ = std::move(out);
  size_ = std::move(sizes);
  face_ = std::move(geometry);
}

AgglomerationStats Agglomerator::run() {
  AgglomerationStats stats;
  const Index nc = mesh_.num_cells(), nf = mesh_.num_faces();
  // Face scores, kept up to date around the cells each round changes: a round changes few
  // cells, and rescoring every face each round would cost more than the merging.
  std::vector<double> scores(nf, 0.0);
  tbb::parallel_for(Index{0}, nf, [&](Index f) { scores[f] = screened_score(f); });
  for (int round = 0; round < options_.rounds; ++round) {
    // The cells beside a face beyond the limits, worst first, then the tiny cells.
    std::vector<std::pair<double, Index>> bad;
    std::vector<Index> rejected;
    for (Index f = 0; f < nf; ++f) {
      if (!face_alive_[f]) continue;
      const double s = scores[f];
      if (s <= 1.0) continue;
      rejected.push_back(f);
      bad.emplace_back(s, mesh_.owner[f]);
      if (mesh_.neighbour[f] != kNoIndex) bad.emplace_back(s, mesh_.neighbour[f]);
    }
    std::sort(bad.begin(), bad.end(), [](const auto& a, const auto& b) { return a > b; });
    std::vector<Index> tiny;
    for (Index c = 0; c < nc; ++c)
      if (cell_alive_[c] && cell_[c].volume < options_.min_volume_ratio * std::pow(size_[c], 3)) tiny.push_back(c);
    Index merged = 0, joined = 0;
    for (Index f : rejected)
      if (face_alive_[f]) joined += join_faces(f);
    for (const auto& [s, c] : bad)
      if (cell_alive_[c] && worst_of(c) > 1.0) merged += try_merge(c, false);
    for (Index c : tiny)
      if (cell_alive_[c] && cell_[c].volume < options_.min_volume_ratio * std::pow(size_[c], 3))
        merged += try_merge(c, true);
    stats.merged += merged;
    stats.joined += joined;
    if (merged == 0 && joined == 0) break;
    for (Index c : changed_)
      if (cell_alive_[c])
        for (Index f : faces_of_[c]) scores[f] = screened_score(f);
    changed_.clear();
  }
  // Each round ends with the scores around what it changed brought up to date.
  for (Index f = 0; f < nf; ++f) stats.bad_faces += face_alive_[f] && scores[f] > 1.0;
  if (stats.merged > 0 || stats.joined > 0) rebuild();
  return stats;
}

}  // namespace

AgglomerationStats agglomerate(PolyMesh& mesh, std::vector<double>& cell_size,
                               const AgglomerationOptions& options, std::vector<FaceGeometry>& face_geometry) {
  Agglomerator merging(mesh, cell_size, options);
  const AgglomerationStats stats = merging.run();
  face_geometry = merging.take_face_geometry();
  return stats;
}

}  // namespace volmesh::cutcell
