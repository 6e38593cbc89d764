// What OpenFOAM's checkMesh asks of the cut-cell mesh, measured with volmesh's own
// measures: face skewness (quality/face_metrics, checkMesh flags faces above 4),
// non-orthogonality (an error from 90°), cell centres behind a face (checkMesh's
// "incorrectly oriented" face pyramids), and the smallest cell relative to its leaf.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "volmesh/core/geometry.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/cutcell/cutcell.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/geometry/polygon_split.hpp"
#include "volmesh/quality/face_metrics.hpp"

namespace volmesh {
namespace {

struct Rejected {
  Index skewed = 0, non_orthogonal = 0, behind = 0;
  double max_skewness = 0.0;
  Index total() const { return skewed + non_orthogonal + behind; }
};

Rejected rejected_faces(const PolyMesh& mesh) {
  const MeshGeometry geometry = mesh_geometry(mesh, build_cell_faces(mesh));
  const std::vector<double> skew = face_skewness(mesh, geometry);
  const std::vector<double> angle = face_non_orthogonality(mesh, geometry);
  Rejected r;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const FaceGeometry& face = geometry.faces[f];
    r.max_skewness = std::max(r.max_skewness, skew[f]);
    r.skewed += skew[f] > 4.0;
    bool behind = face.area_vector.dot(face.centre - geometry.cells[mesh.owner[f]].centre) <= 0.0;
    if (!mesh.is_boundary(f)) {
      r.non_orthogonal += angle[f] >= 90.0;
      behind = behind || face.area_vector.dot(geometry.cells[mesh.neighbour[f]].centre - face.centre) <= 0.0;
    }
    r.behind += behind;
  }
  return r;
}

PolyMesh mesh_of(const char* name, int level, CutcellStats& stats, int merge_rounds = 16) {
  CutcellOptions options;
  options.octree.level = level;
  options.merge_rounds = merge_rounds;
  return cutcell_mesh(*make_builtin_domain(name), options, &stats);
}

TEST(CutcellQuality, BallPassesCheckMeshLimits) {
  for (int level = 3; level <= 5; ++level) {
    CutcellStats stats;
    const PolyMesh mesh = mesh_of("ball", level, stats);
    const Rejected r = rejected_faces(mesh);
    EXPECT_EQ(r.total(), 0) << "level " << level << ": " << r.skewed << " skewed, " << r.non_orthogonal
                            << " non-orthogonal, " << r.behind << " behind a centre";
    EXPECT_EQ(stats.bad_faces, 0) << "level " << level;
    EXPECT_LE(stats.max_skewness, 4.0) << "level " << level;
    EXPECT_LT(stats.max_non_orthogonality, 90.0) << "level " << level;
    EXPECT_GE(stats.min_cell_volume_ratio, 2e-4) << "level " << level;
  }
}

// Multi-material junctions (a plane through a sphere through a cylinder) at level 4: with the
// vertex moves counting the crossings an edge already has, both crossings of an edge crossed
// twice kept and thin pieces merged, checkMesh rejects no face. The smallest cell (5.2e-5 h^3,
// hence the bound) is the tip of a wedge between two surfaces crossing at a junction line,
// cut off where an edge keeps both of its crossings 0.05 of it apart: merged, its face on
// the other surface would be too skewed for checkMesh.
TEST(CutcellQuality, PrimitivesJunctionsLeaveNoThinCellsAndFewRejectedFaces) {
  CutcellStats stats;
  const PolyMesh mesh = mesh_of("primitives", 4, stats);
  EXPECT_TRUE(check_validity(mesh).valid());
  EXPECT_GE(stats.min_cell_volume_ratio, 4e-5);
  EXPECT_EQ(stats.unresolved_vertices, 0);
  // Edges beside the junctions are crossed twice at the deepest level and keep both crossings.
  EXPECT_GT(stats.split_edges, 0);
  const Rejected r = rejected_faces(mesh);
  EXPECT_EQ(r.total(), 0) << r.skewed << " skewed, " << r.non_orthogonal << " non-orthogonal, "
                          << r.behind << " behind a centre";
  EXPECT_LE(r.max_skewness, 4.0);
  EXPECT_DOUBLE_EQ(stats.max_skewness, r.max_skewness);  // the stats measure the whole mesh
  EXPECT_EQ(stats.bad_faces, 0);
}

// Where the pinched-out layer meets the fault, a cell of one region and one of another are
// bent into each other, each one's centre behind a face they share, and neither split alone
// helps: split together, level 4 passes. One face there has a centre on its plane to within
// rounding, which checkMesh (and bad_faces) accept.
TEST(CutcellQuality, Layers6Level4PassesCheckMeshLimits) {
  CutcellStats stats;
  const PolyMesh mesh = mesh_of("layers6", 4, stats);
  const Rejected r = rejected_faces(mesh);
  EXPECT_EQ(r.skewed + r.non_orthogonal, 0) << r.skewed << " skewed, " << r.non_orthogonal << " non-orthogonal";
  EXPECT_EQ(stats.bad_faces, 0);
}

// Where layers end on the box (near its face x = 0 at levels 4 and 5), the splitter's last
// resort for a skewed face and the merging's face joins can make polygons folded over
// themselves, which the polyhedral FEM refuses: a merged polygon is kept only when
// split_polygon, the FEM's own verdict, finds it unfolded.
TEST(CutcellQuality, Layers6HasNoFoldedFaces) {
  for (const auto& [level, base] : {std::pair{4, 3}, std::pair{4, 4}, std::pair{5, 3}}) {
    CutcellOptions options;
    options.octree.level = level;
    options.octree.base_level = base;
    const PolyMesh mesh = cutcell_mesh(*make_builtin_domain("layers6"), options);
    Index folded = 0;
    for (Index f = 0; f < mesh.num_faces(); ++f) folded += split_polygon(mesh.points, mesh.face(f)).folded;
    EXPECT_EQ(folded, 0) << "level " << level << ", base level " << base;
  }
}

// Merging moves no point: the cells stay closed, and a region's volume changes only where
// two of its boundary or interface faces were joined into one warped polygon, by far less
// than the discretisation error (about 1e-2 at this level); the cell count stays within a
// few percent of the unmerged mesh.
TEST(CutcellQuality, MergingKeepsRegionVolumes) {
  CutcellStats merged_stats, plain_stats;
  const PolyMesh merged = mesh_of("primitives", 3, merged_stats);
  const PolyMesh plain = mesh_of("primitives", 3, plain_stats, 0);
  EXPECT_GT(merged_stats.merged_cells, 0);
  EXPECT_EQ(plain_stats.merged_cells, 0);
  EXPECT_LT(merged.num_cells(), plain.num_cells());
  EXPECT_GT(merged.num_cells(), 0.95 * plain.num_cells());
  const ValidityReport a = check_validity(merged), b = check_validity(plain);
  ASSERT_TRUE(a.valid());
  ASSERT_TRUE(b.valid());
  ASSERT_EQ(a.region_volume.size(), b.region_volume.size());
  EXPECT_NEAR(a.total_volume, b.total_volume, 1e-5 * b.total_volume);
  for (const auto& [region, volume] : b.region_volume)
    EXPECT_NEAR(a.region_volume.at(region), volume, 1e-3 * volume) << "region " << region;
  EXPECT_GE(merged_stats.min_cell_volume_ratio, plain_stats.min_cell_volume_ratio);
}

}  // namespace
}  // namespace volmesh
