#include "volmesh/quality/report.hpp"

#include <algorithm>
#include <numeric>

#include "volmesh/quality/face_metrics.hpp"

namespace volmesh {

namespace {

// checkMesh counts a non-orthogonality error where the cosine is at most its SMALL: an angle
// of 90° to rounding, so the count starts this far below 90°.
constexpr double kRightAngleRoundingDeg = 1e-12;

// The face values on the boundary (or off it), in face order.
std::vector<double> select_faces(const PolyMesh& mesh, const std::vector<double>& values,
                                 bool boundary) {
  std::vector<double> out;
  out.reserve(values.size());
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (mesh.is_boundary(f) == boundary) out.push_back(values[f]);
  return out;
}

void count_cells(const CellQuality& q, QualityReport& r) {
  r.cells = static_cast<Index>(q.shape.size());
  for (std::size_t c = 0; c < q.shape.size(); ++c) {
    const double volume = q.volume[c];
    if (volume <= 0.0) ++r.non_positive_cells;
    switch (q.shape[c]) {
      case CellShape::Tetrahedron:
        ++r.tets;
        if (volume < 0.0) ++r.inverted_tets;
        break;
      case CellShape::Hexahedron:
        ++r.hexes;
        if (q.scaled_jacobian[c] < 0.0) ++r.inverted_hexes;
        if (q.scaled_jacobian[c] == 0.0) ++r.degenerate_hexes;
        break;
      case CellShape::Polyhedron:
        ++r.polyhedra;
        break;
    }
  }
}

}  // namespace

QualityReport quality_report(const PolyMesh& mesh, const QualityMeasurements& m) {
  QualityReport r;
  const CellQuality& q = m.cells;
  count_cells(q, r);

  const std::vector<double> internal_ortho = select_faces(mesh, m.faces.non_orthogonality, false);
  r.severely_non_orthogonal_faces =
      static_cast<Index>(std::count_if(internal_ortho.begin(), internal_ortho.end(),
                                       [](double a) { return a > kSevereNonOrthogonalityDeg; }));
  r.highly_skewed_faces =
      static_cast<Index>(std::count_if(m.faces.skewness.begin(), m.faces.skewness.end(),
                                       [](double s) { return s > kCheckMeshSkewness; }));
  const double error_from = kCheckMeshNonOrthogonality - kRightAngleRoundingDeg;
  r.non_orthogonality_errors = static_cast<Index>(std::count_if(
      internal_ortho.begin(), internal_ortho.end(), [&](double a) { return a >= error_from; }));
  r.inverted_face_pyramids = std::accumulate(m.faces.inverted_pyramids.begin(), m.faces.inverted_pyramids.end(), Index{0});

  const auto [vmin, vmax] = std::minmax_element(q.volume.begin(), q.volume.end());
  const bool any = !q.volume.empty();
  r.metrics.push_back(
      summarize("cell_volume", q.volume, make_histogram(any ? *vmin : 0.0, any ? *vmax : 0.0, 20)));
  r.metrics.push_back(summarize("tet_min_dihedral", q.min_dihedral, make_histogram(0, 180, 18)));
  r.metrics.push_back(summarize("tet_max_dihedral", q.max_dihedral, make_histogram(0, 180, 18)));
  r.metrics.push_back(
      summarize("tet_radius_edge_ratio", q.radius_edge_ratio, make_histogram(0, 4, 20)));
  r.metrics.push_back(summarize("tet_aspect_ratio", q.aspect_ratio, make_histogram(1, 11, 20)));
  r.metrics.push_back(
      summarize("hex_scaled_jacobian", q.scaled_jacobian, make_histogram(-1, 1, 20)));
  r.metrics.push_back(summarize("non_orthogonality", internal_ortho, make_histogram(0, 90, 18)));
  r.metrics.push_back(summarize("boundary_non_orthogonality",
                                select_faces(mesh, m.faces.non_orthogonality, true),
                                make_histogram(0, 90, 18)));
  r.metrics.push_back(summarize("skewness", m.faces.skewness, make_histogram(0, 5, 20)));
  // NaN on boundary faces, so only internal faces are summarised.
  r.metrics.push_back(
      summarize("neighbour_volume_ratio", m.faces.volume_ratio, make_histogram(0.5, 16.5, 16)));

  r.min_volume = find_metric(r, "cell_volume")->min;
  r.max_neighbour_volume_ratio = find_metric(r, "neighbour_volume_ratio")->max;
  return r;
}

QualityReport mesh_quality(const PolyMesh& mesh) {
  return quality_report(mesh, measure_quality(mesh));
}

const MetricSummary* find_metric(const QualityReport& report, std::string_view name) {
  for (const MetricSummary& s : report.metrics)
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace volmesh
