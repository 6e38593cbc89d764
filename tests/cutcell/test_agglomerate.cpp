// agglomerate on cells written by hand: a sliver merged into the neighbour of its own region
// and never into another region's, a cell checkMesh rejects merged with the two neighbours
// that pull its centre back, and a small face joined with the face beside it between the
// same two cells.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "agglomerate.hpp"
#include "hand_meshes.hpp"
#include "volmesh/core/geometry.hpp"

namespace volmesh {
namespace {

// Cells below 1e-3 of their size cubed are merged (the mesher's merge_volume_ratio); the
// slivers here are 1e-4 thick, of size 1.
constexpr double kVolumeRatio = 1e-3;
constexpr double kSliver = 1e-4;

cutcell::AgglomerationOptions tiny_cells_merged() {
  cutcell::AgglomerationOptions o;
  o.min_volume_ratio = kVolumeRatio;
  return o;
}

// What a run must do: this many merges and joins, leaving this many cells.
struct Outcome {
  Index merged, joined, cells;
};

// agglomerate on `mesh` (every cell of size 1), checked for the outcome and for what every run
// keeps: no face beyond checkMesh's limits after it, a valid mesh with the same volumes, a
// size per cell, and the face geometry handed back that of the result's faces.
void expect_agglomerated(PolyMesh& mesh, const cutcell::AgglomerationOptions& options, const Outcome& want) {
  const ValidityReport before = check_validity(mesh);
  ASSERT_TRUE(before.valid()) << (before.problems.empty() ? "" : before.problems.front());
  std::vector<double> size(mesh.num_cells(), 1.0);
  std::vector<FaceGeometry> geometry;

  const cutcell::AgglomerationStats stats = cutcell::agglomerate(mesh, size, options, geometry);

  EXPECT_EQ(stats.merged, want.merged);
  EXPECT_EQ(stats.joined, want.joined);
  EXPECT_EQ(stats.bad_faces, 0);
  ASSERT_EQ(mesh.num_cells(), want.cells);
  EXPECT_EQ(size.size(), static_cast<std::size_t>(want.cells));
  test::expect_valid_with_volumes(mesh, before);
  EXPECT_EQ(test::checkmesh_failures(mesh), 0);
  ASSERT_EQ(geometry.size(), static_cast<std::size_t>(mesh.num_faces()));
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const FaceGeometry g = polygon_geometry(mesh.points, mesh.face(f));
    EXPECT_LT((geometry[f].area_vector - g.area_vector).norm(), 1e-12) << "face " << f;
    EXPECT_LT((geometry[f].centre - g.centre).norm(), 1e-12) << "face " << f;
  }
}

// Along x: a box of region 2, a sliver of region 1, a box of region 1, a sliver of region 3.
// The first sliver goes into the box of its region (not the larger neighbour of region 2);
// the last, whose only neighbour is of another region, stays.
TEST(Agglomerate, MergesASliverIntoItsRegionOnly) {
  test::HandMesh hand;
  hand.box({-1, 0, 0}, {0, 1, 1}, 2);
  hand.box({0, 0, 0}, {kSliver, 1, 1}, 1);
  hand.box({kSliver, 0, 0}, {1, 1, 1}, 1);
  const Index lone = hand.box({1, 0, 0}, {1 + kSliver, 1, 1}, 3);
  PolyMesh mesh = hand.build();

  expect_agglomerated(mesh, tiny_cells_merged(), {.merged = 1, .joined = 0, .cells = 3});

  EXPECT_EQ(mesh.cell_region, (std::vector<Index>{2, 1, 3}));
  const MeshGeometry g = mesh_geometry(mesh, build_cell_faces(mesh));
  EXPECT_NEAR(g.cells[1].volume, 1.0, 1e-12);
  EXPECT_NEAR(g.cells[lone - 1].volume, kSliver, 1e-12);
}

// The L [0,1] x [0,0.2] + [0,0.2] x [0,1], whose centre lies behind the two boundary faces
// at its reflex edge (tagged apart: no join between them), with a box of its region beside
// each arm. Merged with one box it is still an L with its centre behind a face; with both, the
// centre is pulled back in front of them.
TEST(Agglomerate, MergesARejectedCellWithTwoNeighboursOfItsRegion) {
  const double a = 0.2;
  test::HandMesh hand;
  hand.prism({{0, 0}, {1, 0}, {1, a}, {a, a}, {a, 1}, {0, 1}}, 0.0, 1.0, 1);
  hand.box({-1, 0, 0}, {0, 1, 1}, 1);
  hand.box({0, -1, 0}, {1, 0, 1}, 1);
  hand.name_face({{1, a, 0}, {a, a, 0}, {a, a, 1}, {1, a, 1}}, "floor");
  hand.name_face({{a, a, 0}, {a, 1, 0}, {a, 1, 1}, {a, a, 1}}, "side");
  PolyMesh mesh = hand.build();
  ASSERT_GT(test::checkmesh_failures(mesh), 0);

  expect_agglomerated(mesh, {}, {.merged = 1, .joined = 0, .cells = 1});
}

// Two boxes of different regions (no merge can help) sharing the plane x = 0.5 as two faces:
// a small triangle at a corner, far from where the line between the cells' centres crosses
// the plane (skewness above 4), and the rest of the square. They are joined into one face.
TEST(Agglomerate, JoinsASkewedFaceWithTheFaceBesideIt) {
  const double d = 0.01;  // the triangle's legs
  const Vec3 a(0.5, 0, 0), q(0.5, d, 0), p(0.5, 0, d), b(0.5, 1, 0), c(0.5, 1, 1), e(0.5, 0, 1);
  test::HandMesh hand;
  hand.point(q);  // on the boxes' sides along x = 0.5: put into the faces there
  hand.point(p);
  // The box between x = x0 and 0.5, its faces outward for x0 < 0.5 (mirrored, reversed).
  const auto box_with_split_side = [&](double x0, Index region) {
    const double x1 = 0.5;
    std::vector<std::vector<Vec3>> faces{
        {{x0, 0, 0}, {x0, 0, 1}, {x0, 1, 1}, {x0, 1, 0}},  // x = x0
        {{x0, 0, 0}, {x1, 0, 0}, {x1, 0, 1}, {x0, 0, 1}},  // y = 0
        {{x0, 1, 0}, {x0, 1, 1}, {x1, 1, 1}, {x1, 1, 0}},  // y = 1
        {{x0, 0, 0}, {x0, 1, 0}, {x1, 1, 0}, {x1, 0, 0}},  // z = 0
        {{x0, 0, 1}, {x1, 0, 1}, {x1, 1, 1}, {x0, 1, 1}},  // z = 1
        {a, q, p},                                          // x = 0.5: the triangle
        {q, b, c, e, p},                                    // and the rest of the square
    };
    if (x0 > x1)
      for (auto& f : faces) std::reverse(f.begin(), f.end());
    return hand.cell(faces, region);
  };
  box_with_split_side(0.0, 1);
  box_with_split_side(1.0, 2);
  PolyMesh mesh = hand.build();
  ASSERT_GT(mesh_quality(mesh).highly_skewed_faces, 0);
  const Index faces = mesh.num_faces();

  expect_agglomerated(mesh, {}, {.merged = 0, .joined = 1, .cells = 2});

  EXPECT_EQ(mesh.num_faces(), faces - 1);
  // The cells share one face now: the whole square, with the triangle's two corners on its sides.
  Index between = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (!mesh.is_boundary(f)) {
      ++between;
      EXPECT_EQ(mesh.face(f).size(), 6u);
      EXPECT_NEAR(polygon_geometry(mesh.points, mesh.face(f)).area_vector.norm(), 1.0, 1e-12);
    }
  EXPECT_EQ(between, 1);
}

}  // namespace
}  // namespace volmesh
