// The repair schedule: passes over the tets that are not positive by the exact test, each
// tried with the cheapest change first, until a pass leaves none or changes nothing.
#include "volmesh/improve/repair.hpp"

#include <algorithm>

#include "exact.hpp"
#include "quality.hpp"
#include "smooth.hpp"
#include "tet_complex.hpp"
#include "topology.hpp"

namespace volmesh::improve {

namespace {

// Each pass changes something or ends the repair; this bounds the passes.
constexpr int kMaxRepairPasses = 32;

bool is_positive(const TetComplex& mesh, Index t) {
  const Tet& c = mesh.tet(t);
  return positive(mesh.point(c[0]), mesh.point(c[1]), mesh.point(c[2]), mesh.point(c[3]));
}

std::vector<Index> bad_tets(const TetComplex& mesh) {
  std::vector<Index> bad;
  for (Index t = 0; t < mesh.num_slots(); ++t)
    if (mesh.alive(t) && !is_positive(mesh, t)) bad.push_back(t);
  return bad;
}

// A sliding point merged into a point of its triangle or edge, when that raises the worst
// quality of its star (a flat tet on the surface goes with the point).
bool contract_sliding(TetComplex& mesh, Index gone, Index kept) {
  if (mesh.freedom(gone) != Freedom::Slides) return false;
  const std::optional<double> after = contraction_quality(mesh, gone, kept);
  if (!after || !raises(*after, mesh.min_quality(mesh.star(gone)))) return false;
  contract(mesh, gone, kept);
  return true;
}

// Points that rounding put at the same place, merged where they share an edge, the later into
// the earlier: the tets holding both go, the others keep their coordinates, so nothing else
// changes shape, the surface included. The merged point keeps the surface pieces of both, so
// it no longer slides.
long long merge_coincident(TetComplex& mesh) {
  long long merged = 0;
  for (Index v = 0; v < mesh.num_points(); ++v) {
    if (mesh.star(v).empty()) continue;
    std::vector<Index> twins;
    for (const Index t : mesh.star(v))
      for (const Index w : mesh.tet(t))
        if (w < v && mesh.point(w) == mesh.point(v)) twins.push_back(w);
    std::sort(twins.begin(), twins.end());
    twins.erase(std::unique(twins.begin(), twins.end()), twins.end());
    for (const Index w : twins)
      if (merge_allowed(mesh, v, w)) {
        contract(mesh, v, w);
        mesh.pin(w);
        ++merged;
        break;
      }
  }
  return merged;
}

bool repair_at(TetComplex& mesh, Index t, RepairStats& stats) {
  const Tet corners = mesh.tet(t);
  for (const auto& e : kTetEdges)
    if (remove_edge(mesh, corners[e[0]], corners[e[1]])) {
      ++stats.flips;
      return true;
    }
  for (int f = 0; f < 4; ++f)
    if (remove_faces(mesh, t, f)) {
      ++stats.flips;
      return true;
    }
  for (const Index v : corners)
    if (mesh.freedom(v) != Freedom::Pinned && smooth_point(mesh, v)) {
      ++stats.smoothed;
      return true;
    }
  for (const auto& e : kTetEdges) {
    const Index a = corners[e[0]], b = corners[e[1]];
    if (contract_edge(mesh, a, b) || contract_edge(mesh, b, a) || contract_sliding(mesh, a, b) ||
        contract_sliding(mesh, b, a)) {
      ++stats.contractions;
      return true;
    }
  }
  return false;
}

}  // namespace

RepairStats repair_flat_tets(TetMesh& mesh, const std::vector<Slide>& slides) {
  RepairStats stats;
  TetComplex complex(mesh, slides);
  std::vector<Index> bad = bad_tets(complex);
  stats.bad_before = static_cast<Index>(bad.size());
  if (!bad.empty()) {
    stats.contractions += merge_coincident(complex);
    bad = bad_tets(complex);
  }
  for (int pass = 0; pass < kMaxRepairPasses && !bad.empty(); ++pass) {
    bool changed = false;
    for (const Index t : bad)
      if (complex.alive(t) && !is_positive(complex, t)) changed |= repair_at(complex, t, stats);
    bad = bad_tets(complex);
    if (!changed) break;
  }
  stats.bad_after = static_cast<Index>(bad.size());
  if (stats.bad_before > 0) complex.write_to(mesh, true);
  return stats;
}

}  // namespace volmesh::improve
