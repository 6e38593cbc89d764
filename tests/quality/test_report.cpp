#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>

#include "../support/unit_cube_meshes.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/quality/report.hpp"

namespace volmesh {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

Index total(const Histogram& h) {
  return std::accumulate(h.counts.begin(), h.counts.end(), Index{0});
}

const MetricSummary& metric(const QualityReport& r, std::string_view name) {
  const MetricSummary* s = find_metric(r, name);
  if (s == nullptr) throw std::runtime_error("no metric " + std::string(name));
  return *s;
}

// Every histogram counts each summarised value exactly once, and the counts are the
// numbers of elements each metric applies to.
void expect_consistent(const QualityReport& r, const PolyMesh& mesh) {
  Index boundary = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) boundary += mesh.is_boundary(f);
  const Index internal = mesh.num_faces() - boundary;
  EXPECT_EQ(r.cells, mesh.num_cells());
  EXPECT_EQ(r.tets + r.hexes + r.polyhedra, r.cells);
  ASSERT_EQ(r.metrics.size(), 10u);
  for (const MetricSummary& s : r.metrics) EXPECT_EQ(total(s.histogram), s.count) << s.name;
  EXPECT_EQ(metric(r, "cell_volume").count, r.cells);
  EXPECT_EQ(metric(r, "tet_min_dihedral").count, r.tets);
  EXPECT_EQ(metric(r, "tet_max_dihedral").count, r.tets);
  EXPECT_EQ(metric(r, "tet_radius_edge_ratio").count, r.tets);
  EXPECT_EQ(metric(r, "tet_aspect_ratio").count, r.tets);
  EXPECT_EQ(metric(r, "hex_scaled_jacobian").count, r.hexes);
  EXPECT_EQ(metric(r, "non_orthogonality").count, internal);
  EXPECT_EQ(metric(r, "boundary_non_orthogonality").count, boundary);
  EXPECT_EQ(metric(r, "skewness").count, mesh.num_faces());
  EXPECT_EQ(metric(r, "neighbour_volume_ratio").count, internal);
}

TEST(QualityReport, CubeGridIsPerfect) {
  const PolyMesh mesh = to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2}));
  const QualityReport r = mesh_quality(mesh);
  expect_consistent(r, mesh);
  EXPECT_EQ(r.hexes, 8);
  EXPECT_EQ(r.inverted_hexes + r.degenerate_hexes + r.non_positive_cells, 0);
  const MetricSummary& sj = metric(r, "hex_scaled_jacobian");
  EXPECT_DOUBLE_EQ(sj.min, 1.0);
  EXPECT_EQ(sj.histogram.counts.back(), 8);
  EXPECT_NEAR(metric(r, "non_orthogonality").max, 0.0, 1e-12);
  EXPECT_NEAR(metric(r, "boundary_non_orthogonality").max, 0.0, 1e-12);
  EXPECT_NEAR(metric(r, "skewness").max, 0.0, 1e-12);
  EXPECT_EQ(metric(r, "non_orthogonality").histogram.counts.front(), 12);
  EXPECT_NEAR(r.min_volume, 0.125, 1e-15);
  EXPECT_NEAR(r.max_neighbour_volume_ratio, 1.0, 1e-14);
  EXPECT_EQ(r.severely_non_orthogonal_faces + r.highly_skewed_faces, 0);
}

TEST(QualityReport, KuhnTetsAllLandInTheirBins) {
  const PolyMesh mesh = to_poly_mesh(kuhn_tet_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2}));
  const QualityReport r = mesh_quality(mesh);
  expect_consistent(r, mesh);
  EXPECT_EQ(r.tets, 48);
  EXPECT_EQ(r.inverted_tets, 0);
  // Every Kuhn tet: dihedrals 45°..90°, radius-edge sqrt(3)/2, aspect ≈ 1.394.
  EXPECT_EQ(metric(r, "tet_min_dihedral").histogram.counts[4], 48);  // [40, 50)
  const Histogram& max_dihedral = metric(r, "tet_max_dihedral").histogram;
  EXPECT_EQ(max_dihedral.counts[8] + max_dihedral.counts[9], 48);  // 90° is a bin edge
  EXPECT_NEAR(metric(r, "tet_min_dihedral").min, 45.0, 1e-12);
  EXPECT_NEAR(metric(r, "tet_max_dihedral").max, 90.0, 1e-12);
  EXPECT_EQ(metric(r, "tet_radius_edge_ratio").histogram.counts[4], 48);  // [0.8, 1.0)
  EXPECT_EQ(metric(r, "tet_aspect_ratio").histogram.counts[0], 48);       // [1, 1.5)
  EXPECT_NEAR(r.min_volume, 1.0 / 48.0, 1e-15);
}

TEST(QualityReport, BigCubeNextToFourSmallOnesHasVolumeRatioEight) {
  const PolyMesh mesh = test::big_cube_next_to_four_small();
  const QualityReport r = mesh_quality(mesh);
  expect_consistent(r, mesh);
  EXPECT_EQ(r.hexes, 4);
  EXPECT_EQ(r.polyhedra, 1);  // the big cube has 9 faces
  EXPECT_NEAR(r.max_neighbour_volume_ratio, 8.0, 1e-13);
  EXPECT_NEAR(r.min_volume, 0.125, 1e-15);
  EXPECT_NEAR(metric(r, "non_orthogonality").max, std::acos(3.0 / std::sqrt(11.0)) * kDeg, 1e-12);
  EXPECT_NEAR(metric(r, "skewness").max, 1.0 / 3.0, 1e-14);
  // Four transition faces at ratio 8, four between small cubes at ratio 1.
  const Histogram& ratio = metric(r, "neighbour_volume_ratio").histogram;
  EXPECT_EQ(ratio.counts[0], 4);  // [0.5, 1.5)
  EXPECT_EQ(ratio.counts[7], 4);  // [7.5, 8.5)
}

TEST(QualityReport, CountsInvertedAndDegenerateHexes) {
  // Three separate hexes: a unit cube, one with its edge 1-5 collapsed, one mirrored.
  HexMesh h;
  for (int copy = 0; copy < 3; ++copy) {
    for (Vec3 p : test::unit_cube_corners()) {
      p.x() += 2.0 * copy;
      h.points.push_back(p);
    }
    std::array<Index, 8> cell;
    for (Index k = 0; k < 8; ++k) cell[k] = 8 * copy + k;
    h.cells.push_back(cell);
  }
  h.points[8 + 5] = h.points[8 + 1];
  for (Index k = 16; k < 24; ++k) h.points[k].z() = -h.points[k].z();
  h.cell_region.assign(3, 1);
  const PolyMesh mesh = to_poly_mesh(h);
  const QualityReport r = mesh_quality(mesh);
  expect_consistent(r, mesh);
  EXPECT_EQ(r.hexes, 3);
  EXPECT_EQ(r.degenerate_hexes, 1);
  EXPECT_EQ(r.inverted_hexes, 1);
  EXPECT_EQ(r.non_positive_cells, 1);  // the collapsed hex still has volume
  EXPECT_DOUBLE_EQ(metric(r, "hex_scaled_jacobian").min, -1.0);
  EXPECT_NEAR(r.min_volume, -1.0, 1e-15);
  const Histogram& sj = metric(r, "hex_scaled_jacobian").histogram;
  EXPECT_EQ(sj.counts[0], 1);   // -1
  EXPECT_EQ(sj.counts[10], 1);  // 0
  EXPECT_EQ(sj.counts[19], 1);  // 1
}

TEST(QualityReport, CountsInvertedTets) {
  TetMesh t;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
              {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}};
  t.cells = {{0, 1, 2, 3}, {4, 6, 5, 7}};  // the second one flipped
  t.cell_region = {1, 1};
  const PolyMesh mesh = to_poly_mesh(t);
  const QualityReport r = mesh_quality(mesh);
  expect_consistent(r, mesh);
  EXPECT_EQ(r.tets, 2);
  EXPECT_EQ(r.inverted_tets, 1);
  EXPECT_EQ(r.non_positive_cells, 1);
  EXPECT_NEAR(r.min_volume, -1.0 / 6.0, 1e-15);
}

TEST(QualityReport, FlagsFacesPastCheckMeshThresholds) {
  // A 1×1×2 column whose middle layer of points is pushed far sideways: the shared face
  // stays planar but the centre-to-centre line runs almost along it.
  HexMesh h = structured_hex_mesh(Vec3::Zero(), Vec3(1, 1, 2), {1, 1, 2});
  for (Vec3& p : h.points)
    if (p.z() == 1.0) p.x() += 6.0;
  const PolyMesh mesh = to_poly_mesh(h);
  const QualityReport r = mesh_quality(mesh);
  expect_consistent(r, mesh);
  // Centres (3.5, 0.5, 0.5) and (3.5, 0.5, 1.5), shared face [6,7]×[0,1] at z = 1: d and
  // the normal are both vertical (orthogonal), but the line between the centres crosses the
  // face plane 3 away from its centre, 6 times the face's half-width: skewness 6.
  EXPECT_NEAR(metric(r, "non_orthogonality").max, 0.0, 1e-12);
  EXPECT_EQ(r.severely_non_orthogonal_faces, 0);
  // The bottom and top boundary faces are as far off their cell centres: skewness 6 too.
  EXPECT_NEAR(metric(r, "skewness").max, 6.0, 1e-12);
  EXPECT_EQ(r.highly_skewed_faces, 3);
}

TEST(QualityReport, EmptyMeshHasNoExtremes) {
  const QualityReport r = mesh_quality(PolyMesh{});
  EXPECT_EQ(r.cells, 0);
  EXPECT_TRUE(std::isnan(r.min_volume));
  EXPECT_TRUE(std::isnan(r.max_neighbour_volume_ratio));
}

TEST(CellQualityArrays, OneValuePerCellNaNWhereNotApplicable) {
  const PolyMesh mesh = test::big_cube_next_to_four_small();
  const std::vector<NamedArray> arrays = cell_quality_arrays(mesh);
  ASSERT_EQ(arrays.size(), 10u);
  const auto get = [&](std::string_view name) -> const std::vector<double>& {
    for (const NamedArray& a : arrays)
      if (a.name == name) return a.values;
    throw std::runtime_error("no array " + std::string(name));
  };
  for (const NamedArray& a : arrays) EXPECT_EQ(a.values.size(), 5u) << a.name;
  EXPECT_DOUBLE_EQ(get("volume")[0], 1.0);
  EXPECT_TRUE(std::isnan(get("scaled_jacobian")[0]));  // the big cube is a polyhedron
  for (int c = 1; c < 5; ++c) {
    EXPECT_DOUBLE_EQ(get("volume")[c], 0.125);
    EXPECT_DOUBLE_EQ(get("scaled_jacobian")[c], 1.0);
    EXPECT_NEAR(get("volume_ratio")[c], 8.0, 1e-13);
    EXPECT_NEAR(get("skewness")[c], 1.0 / 3.0, 1e-14);
  }
  for (int c = 0; c < 5; ++c) {
    EXPECT_TRUE(std::isnan(get("min_dihedral")[c]));
    EXPECT_NEAR(get("non_orthogonality")[c], std::acos(3.0 / std::sqrt(11.0)) * kDeg, 1e-12);
    EXPECT_NEAR(get("boundary_non_orthogonality")[c], 0.0, 1e-12);
  }
  EXPECT_NEAR(get("volume_ratio")[0], 8.0, 1e-13);
}

TEST(CellQualityArrays, InteriorCellHasNoBoundaryValue) {
  const PolyMesh mesh = to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {3, 3, 3}));
  const QualityMeasurements m = measure_quality(mesh);
  EXPECT_TRUE(std::isnan(m.cells.boundary_non_orthogonality[13]));  // the centre cell
  EXPECT_NEAR(m.cells.boundary_non_orthogonality[0], 0.0, 1e-12);
  EXPECT_EQ(m.faces.skewness.size(), static_cast<std::size_t>(mesh.num_faces()));
}

}  // namespace
}  // namespace volmesh
