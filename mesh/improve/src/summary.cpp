// The whole-mesh figures: per tet in parallel, then reduced in tet order (deterministic).
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <limits>

#include "quality.hpp"
#include "volmesh/improve/improve.hpp"
#include "volmesh/quality/tet_metrics.hpp"

namespace volmesh::improve {

namespace {

constexpr double kSmallAngleDeg = 10.0;

}  // namespace

QualitySummary summarize_quality(const TetMesh& mesh) {
  const std::size_t n = mesh.cells.size();
  std::vector<TetMetrics> metrics(n);
  std::vector<double> quality(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t c) {
    const auto& t = mesh.cells[c];
    metrics[c] = tet_metrics(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]],
                             mesh.points[t[3]]);
    quality[c] = tet_quality(mesh.points, t);
  });
  QualitySummary s;
  s.tets = mesh.num_cells();
  s.points = mesh.num_points();
  if (n == 0) return s;
  s.min_dihedral_deg = std::numeric_limits<double>::infinity();
  s.min_quality = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < n; ++c) {
    s.min_dihedral_deg = std::min(s.min_dihedral_deg, metrics[c].min_dihedral_deg);
    s.max_dihedral_deg = std::max(s.max_dihedral_deg, metrics[c].max_dihedral_deg);
    s.max_radius_edge = std::max(s.max_radius_edge, metrics[c].radius_edge_ratio);
    s.below_10_degrees += metrics[c].min_dihedral_deg < kSmallAngleDeg;
    s.min_quality = std::min(s.min_quality, quality[c]);
  }
  return s;
}

}  // namespace volmesh::improve
