#pragma once
// The quality report of `volmesh check`: element counts, the checkMesh-style failure counts
// and a summary with histogram of every metric.
#include <string_view>
#include <vector>

#include "volmesh/quality/histogram.hpp"
#include "volmesh/quality/measurements.hpp"

namespace volmesh {

inline constexpr double kSevereNonOrthogonalityDeg = 70.0;  // checkMesh's nonOrthThreshold

struct QualityReport {
  Index cells = 0, tets = 0, hexes = 0, polyhedra = 0;
  Index inverted_tets = 0;                  // volume < 0
  Index inverted_hexes = 0;                 // scaled Jacobian < 0
  Index degenerate_hexes = 0;               // scaled Jacobian == 0 (collapsed edge, flat corner)
  Index non_positive_cells = 0;             // volume <= 0, any shape
  Index severely_non_orthogonal_faces = 0;  // internal faces above 70° (checkMesh splits
                                            // these into "severe" and "> 90°" errors)
  Index highly_skewed_faces = 0;            // faces above kCheckMeshSkewness, boundary faces included
  // What makes checkMesh fail, not only warn:
  Index non_orthogonality_errors = 0;  // internal faces at 90° or more
  Index inverted_face_pyramids = 0;    // cell centres behind a face, per face and side
  double min_volume = 0.0;                  // NaN without cells
  double max_neighbour_volume_ratio = 0.0;  // NaN without internal faces
  // Always these, in this order (count 0 when no element of that kind exists):
  //   name                        values                      histogram bins
  //   cell_volume                 every cell                  20 over [min, max]
  //   tet_min_dihedral            tets, degrees               0..180 by 10
  //   tet_max_dihedral            tets, degrees               0..180 by 10
  //   tet_radius_edge_ratio       tets                        0..4 by 0.2
  //   tet_aspect_ratio            tets                        1..11 by 0.5
  //   hex_scaled_jacobian         hexes                       -1..1 by 0.1
  //   non_orthogonality           internal faces, degrees     0..90 by 5
  //   boundary_non_orthogonality  boundary faces, degrees     0..90 by 5
  //   skewness                    every face                  0..5 by 0.25
  //   neighbour_volume_ratio      internal faces              0.5..16.5 by 1
  // Values outside a histogram's range count in its end bins. The volume ratio bins are
  // centred on integers so that an octree's 2:1 transitions (ratio 8) sit mid-bin.
  // non_orthogonality's max is checkMesh's "Mesh non-orthogonality Max"; its mean is the mean angle
  // (checkMesh prints the angle of the mean cosine). skewness's max is checkMesh's "Max skewness".
  std::vector<MetricSummary> metrics;
};

QualityReport quality_report(const PolyMesh& mesh, const QualityMeasurements& measurements);
// measure_quality + quality_report.
QualityReport mesh_quality(const PolyMesh& mesh);

// The summary with this name, or nullptr.
const MetricSummary* find_metric(const QualityReport& report, std::string_view name);

}  // namespace volmesh
