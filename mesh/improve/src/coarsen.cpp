// The coarsening schedule: passes over the points in order, interior points then sliding
// boundary points, each merged into the neighbour that leaves the best worst quality, until a
// pass merges none.
#include "volmesh/improve/coarsen.hpp"

#include <algorithm>
#include <string>

#include "tet_complex.hpp"
#include "topology.hpp"
#include "volmesh/improve/improve.hpp"

namespace volmesh::improve {

namespace {

constexpr int kMaxCoarsenPasses = 16;

std::vector<Index> neighbours(const TetComplex& mesh, Index v) {
  std::vector<Index> out;
  for (const Index t : mesh.star(v))
    for (const Index w : mesh.tet(t))
      if (w != v) out.push_back(w);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Merges each point of the given freedom into its best neighbour, where allowed; returns how
// many went.
long long contract_points(TetComplex& mesh, Freedom kind, double floor) {
  long long merged = 0;
  for (Index v = 0; v < mesh.num_points(); ++v) {
    if (mesh.freedom(v) != kind || mesh.star(v).empty()) continue;
    const double threshold = std::min(floor, mesh.min_quality(mesh.star(v)));
    Index best = kNoIndex;
    double best_quality = threshold;
    for (const Index w : neighbours(mesh, v)) {
      const std::optional<double> q = contraction_quality(mesh, v, w);
      if (q && *q >= best_quality && (best == kNoIndex || *q > best_quality)) {
        best = w;
        best_quality = *q;
      }
    }
    if (best == kNoIndex) continue;
    contract(mesh, v, best);
    ++merged;
  }
  return merged;
}

}  // namespace

CoarsenStats coarsen_tet_mesh(TetMesh& mesh, const CoarsenOptions& options) {
  require_positive_tets(mesh, "the mesh to coarsen");
  CoarsenStats stats;
  stats.points_before = mesh.num_points();
  stats.tets_before = mesh.num_cells();
  TetComplex complex(mesh, options.slides);
  for (int pass = 0; pass < kMaxCoarsenPasses; ++pass) {
    const long long interior = contract_points(complex, Freedom::Free, options.quality_floor);
    const long long boundary = contract_points(complex, Freedom::Slides, options.quality_floor);
    stats.interior += interior;
    stats.boundary += boundary;
    ++stats.passes;
    report(options.progress, "coarsening (pass " + std::to_string(pass + 1) + ")",
           static_cast<double>(pass + 1) / kMaxCoarsenPasses);
    if (interior + boundary == 0) break;
  }
  complex.write_to(mesh);
  stats.points_after = mesh.num_points();
  stats.tets_after = mesh.num_cells();
  return stats;
}

}  // namespace volmesh::improve
