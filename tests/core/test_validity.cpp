#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/unit_cube_meshes.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/core/validity.hpp"

namespace volmesh {
namespace {

TEST(Validity, HangingNodeMeshIsClosedAndConforming) {
  const PolyMesh p = test::big_cube_next_to_four_small(true);
  const ValidityReport r = check_validity(p);
  EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
  EXPECT_DOUBLE_EQ(r.total_volume, 1.5);
  EXPECT_DOUBLE_EQ(r.region_volume.at(1), 1.0);
  EXPECT_DOUBLE_EQ(r.region_volume.at(2), 0.5);
  EXPECT_DOUBLE_EQ(r.min_cell_volume, 0.125);
}

TEST(Validity, FlippedTetIsReportedInverted) {
  TetMesh t;  // alone, a reversed tet owns its faces, which then point inward
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  t.cells = {{0, 2, 1, 3}};
  t.cell_region = {1};
  const ValidityReport r = check_validity(to_poly_mesh(t));
  EXPECT_FALSE(r.valid());
  EXPECT_EQ(r.non_positive_cells, 1);
  EXPECT_DOUBLE_EQ(r.total_volume, -1.0 / 6.0);
}

TEST(Validity, MissingVertexOnAnEdgeIsATJunction) {
  PolyMesh p = test::big_cube_next_to_four_small();
  // Drop the mid-edge vertex (1,0,0.5) from the big cube's y = 0 face: geometrically the
  // same face, but the cell no longer closes edge by edge.
  for (Index f = 0; f < p.num_faces(); ++f) {
    auto loop = p.face(f);
    if (loop.size() != 5 || p.owner[f] != 0) continue;
    std::vector<Index> shorter;
    for (Index v : loop)
      if (!(p.points[v].x() == 1.0 && p.points[v].z() == 0.5 && p.points[v].y() == 0.0))
        shorter.push_back(v);
    if (shorter.size() == 4) {
      PolyMesh q;
      q.points = p.points;
      q.cell_region = p.cell_region;
      q.tag_names = p.tag_names;
      for (Index g = 0; g < p.num_faces(); ++g) {
        if (g == f)
          q.add_face(shorter, p.owner[g], p.neighbour[g], p.face_tag[g]);
        else
          q.add_face(p.face(g), p.owner[g], p.neighbour[g], p.face_tag[g]);
      }
      const ValidityReport r = check_validity(q);
      EXPECT_EQ(r.open_cells, 0);  // the area vectors still sum to zero
      EXPECT_EQ(r.unmatched_cell_edges, 1);
      EXPECT_GT(r.open_region_boundary_edges, 0);
      EXPECT_FALSE(r.valid());
      return;
    }
  }
  FAIL() << "face not found";
}

TEST(Validity, MissingFaceMakesAnOpenCell) {
  PolyMesh p = to_poly_mesh(test::unit_cube_hex());
  PolyMesh q;
  q.points = p.points;
  q.cell_region = p.cell_region;
  q.tag_names = p.tag_names;
  for (Index f = 1; f < p.num_faces(); ++f) q.add_face(p.face(f), 0, kNoIndex, 0);
  const ValidityReport r = check_validity(q);
  EXPECT_EQ(r.open_cells, 1);
  EXPECT_FALSE(r.valid());
}

TEST(Validity, BadIndicesAreReportedNotFollowed) {
  PolyMesh p = to_poly_mesh(test::unit_cube_hex());
  p.face_vertices[3] = 99;
  const ValidityReport r = check_validity(p);
  EXPECT_EQ(r.bad_indices, 1);
  ASSERT_FALSE(r.problems.empty());
  EXPECT_NE(r.problems[0].find("vertex 99 out of range"), std::string::npos);
}

TEST(Validity, DuplicateFaceIsReported) {
  PolyMesh p = to_poly_mesh(test::unit_cube_hex());
  p.add_face(p.face(0), 0, kNoIndex, 0);
  EXPECT_EQ(check_validity(p).duplicate_faces, 1);
}

// A cube whose bottom face a b c d is cut into a b c, a needle a c m with m on the diagonal
// a c up to one unit in the last place, and m c d a: closed edge by edge, and the needle's
// area is not exactly zero.
TEST(Validity, AFaceWithItsVerticesInALineIsDegenerate) {
  const PolyMesh p = to_poly_mesh(test::unit_cube_hex());
  PolyMesh q;
  q.points = p.points;
  q.cell_region = p.cell_region;
  q.tag_names = p.tag_names;
  bool cut = false;
  for (Index f = 0; f < p.num_faces(); ++f) {
    const auto loop = p.face(f);
    const bool bottom = std::all_of(loop.begin(), loop.end(), [&](Index v) { return p.points[v].z() == 0.0; });
    if (!bottom) {
      q.add_face(loop, p.owner[f], p.neighbour[f], p.face_tag[f]);
      continue;
    }
    const Index a = loop[0], b = loop[1], c = loop[2], d = loop[3];
    Vec3 m = p.points[a] + 0.3 * (p.points[c] - p.points[a]);
    m.y() = std::nextafter(m.y(), 1.0);
    const Index mi = static_cast<Index>(q.points.size());
    q.points.push_back(m);
    q.add_face(std::vector<Index>{a, b, c}, p.owner[f], kNoIndex, p.face_tag[f]);
    q.add_face(std::vector<Index>{a, c, mi}, p.owner[f], kNoIndex, p.face_tag[f]);
    q.add_face(std::vector<Index>{mi, c, d, a}, p.owner[f], kNoIndex, p.face_tag[f]);
    const Vec3 needle = (p.points[c] - p.points[a]).cross(m - p.points[a]);
    ASSERT_GT(needle.norm(), 0.0);  // not caught by an exact zero test
    ASSERT_LT(needle.norm(), 1e-15);
    cut = true;
  }
  ASSERT_TRUE(cut);
  const ValidityReport r = check_validity(q);
  EXPECT_EQ(r.open_cells, 0);
  EXPECT_EQ(r.unmatched_cell_edges, 0);
  EXPECT_EQ(r.degenerate_faces, 1);
  EXPECT_FALSE(r.valid());
  ASSERT_FALSE(r.problems.empty());
  EXPECT_NE(r.problems[0].find("zero area"), std::string::npos) << r.problems[0];
}

TEST(Geometry, CentroidsOfAnAsymmetricCell) {
  // Hex [0,2]x[0,1]x[0,1]: volume 2, centroid (1, .5, .5); faces have centres at their middles.
  const PolyMesh p = to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3(2, 1, 1), {1, 1, 1}));
  const MeshGeometry g = mesh_geometry(p, build_cell_faces(p));
  EXPECT_NEAR(g.cells[0].volume, 2.0, 1e-15);
  EXPECT_NEAR((g.cells[0].centre - Vec3(1, 0.5, 0.5)).norm(), 0.0, 1e-15);
  // A pentagon face with a mid-edge vertex keeps the centroid of the square.
  std::vector<Vec3> pts{{0, 0, 0}, {1, 0, 0}, {1, 0.5, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<Index> loop{0, 1, 2, 3, 4};
  const FaceGeometry fg = polygon_geometry(pts, loop);
  EXPECT_NEAR((fg.area_vector - Vec3(0, 0, 1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((fg.centre - Vec3(0.5, 0.5, 0)).norm(), 0.0, 1e-15);
}

}  // namespace
}  // namespace volmesh
