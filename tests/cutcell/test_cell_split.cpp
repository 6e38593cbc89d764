// M3C on the unit cube alone: pieces closed edge by edge, their volumes exact for planar
// interfaces and summing to the cube, face and cell interface points at the junctions.
#include <gtest/gtest.h>

#include "cell_planes.hpp"
#include "unit_cube.hpp"
#include "volmesh/domain/analytic_csg.hpp"

namespace volmesh {
namespace {

using cutcell::CellSplit;
using cutcell::LoopMethod;

// Volume per region (asserting every piece closes), and the total.
std::map<Index, double> region_volumes(const test::UnitCube& cube, const CellSplit& split) {
  const std::vector<Vec3> points = test::all_points(cube.input, split);
  const auto faces = test::piece_faces(cube.input, split);
  std::map<Index, double> out;
  double total = 0.0;
  for (std::size_t p = 0; p < split.pieces.size(); ++p) {
    const double v = test::closed_piece_volume(points, faces[p]);
    EXPECT_GT(v, 0.0) << "piece " << p;
    out[split.pieces[p].region] += v;
    total += v;
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  return out;
}

// The solid below the plane n . x = c, inside a box around the cube: region 1, 0 above.
AnalyticDomain below_plane(const Vec3& normal, double c) {
  const Vec3 n = normal.normalized();
  return solid_domain(Solid(box(Vec3::Constant(-2), Vec3::Constant(3))) &
                      half_space(n * (c / normal.norm()), n));
}

TEST(CellSplit, PlaneParallelToAFace) {
  const AnalyticDomain d = below_plane(Vec3::UnitZ(), 0.3);
  const test::UnitCube cube = test::unit_cube(d);
  const CellSplit split = cutcell::split_cell(cube.input);
  ASSERT_EQ(split.pieces.size(), 2u);
  EXPECT_EQ(split.triangles.size(), 2u);  // the square cut: two triangles
  const auto v = region_volumes(cube, split);
  EXPECT_NEAR(v.at(1), 0.3, 1e-12);
  EXPECT_NEAR(v.at(0), 0.7, 1e-12);
}

TEST(CellSplit, TiltedPlaneCutsAHexagon) {
  // x + y + z <= 1.2: the cube below is the corner tet minus three corner tets.
  const AnalyticDomain d = below_plane(Vec3::Ones(), 1.2);
  const test::UnitCube cube = test::unit_cube(d);
  const CellSplit split = cutcell::split_cell(cube.input);
  ASSERT_EQ(split.pieces.size(), 2u);
  const double c = 1.2;
  const auto v = region_volumes(cube, split);
  EXPECT_NEAR(v.at(1), (c * c * c - 3 * (c - 1) * (c - 1) * (c - 1)) / 6.0, 1e-12);
}

TEST(CellSplit, CurvedSurfaceOverTheCell) {
  // A large ball whose surface crosses the cell: a smooth component, no feature.
  const Vec3 centre(-1.8, -2.1, -2.4);
  const AnalyticDomain d = solid_domain(sphere(centre, 4.0));
  const test::UnitCube cube = test::unit_cube(d);
  const CellSplit split = cutcell::split_cell(cube.input);
  ASSERT_EQ(split.loops.size(), 1u);
  EXPECT_NE(split.loops[0], LoopMethod::feature_fan);
  const auto v = region_volumes(cube, split);
  // Within the sagitta of the cut over the cell of the true volume, sampled finely.
  double inside = 0.0;
  const int n = 60;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        inside += (Vec3(i + 0.5, j + 0.5, k + 0.5) / n - centre).norm() <= 4.0;
  EXPECT_NEAR(v.at(1), inside / (n * n * n), 0.02);
}

TEST(CellSplit, BallAroundACornerLooksLikeACorner) {
  // Seen by one cell, a ball of radius 0.6 around corner 0 has three orthogonal normals on
  // its three edge points: EMC reads a corner where their tangent planes meet.
  const AnalyticDomain d = solid_domain(sphere(Vec3::Zero(), 0.6));
  const test::UnitCube cube = test::unit_cube(d);
  const CellSplit split = cutcell::split_cell(cube.input);
  const auto v = region_volumes(cube, split);
  EXPECT_NEAR(v.at(1), 0.216, 1e-12);
}

TEST(CellSplit, BoxEdgeThroughTheCellIsKeptSharp) {
  // Region 1 = {x < 0.7, y < 0.6}: the feature edge runs along z through the cell.
  const AnalyticDomain d =
      solid_domain(box(Vec3(-2, -2, -2), Vec3(0.7, 0.6, 3)));
  const test::UnitCube cube = test::unit_cube(d);
  const CellSplit split = cutcell::split_cell(cube.input);
  const auto v = region_volumes(cube, split);
  EXPECT_NEAR(v.at(1), 0.42, 1e-12);
  ASSERT_EQ(split.loops.size(), 1u);
  EXPECT_TRUE(split.loops[0] == LoopMethod::feature_split || split.loops[0] == LoopMethod::feature_fan);
}

TEST(CellSplit, BoxCornerInsideTheCellIsAFeaturePoint) {
  const AnalyticDomain d = solid_domain(box(Vec3(-2, -2, -2), Vec3(0.7, 0.6, 0.4)));
  const test::UnitCube cube = test::unit_cube(d);
  const CellSplit split = cutcell::split_cell(cube.input);
  const auto v = region_volumes(cube, split);
  EXPECT_NEAR(v.at(1), 0.7 * 0.6 * 0.4, 1e-12);
  ASSERT_EQ(split.loops.size(), 1u);
  EXPECT_EQ(split.loops[0], LoopMethod::feature_fan);
  ASSERT_EQ(split.new_points.size(), 1u);
  EXPECT_LT((split.new_points[0] - Vec3(0.7, 0.6, 0.4)).norm(), 1e-12);
}

// Labelled boxes: later ones win (analytic_csg.hpp), the first covers the cube.
AnalyticDomain layers(const std::vector<std::pair<Box, Index>>& boxes) {
  std::vector<Layer> l;
  for (const auto& [b, label] : boxes) l.push_back({box(b.lo, b.hi), label});
  return layered_domain(l);
}

TEST(CellSplit, TJunctionJoinsTwoFaceInterfacePoints) {
  // Region 1 on x < 0.4; on x > 0.4, region 2 below y = 0.55 and region 3 above.
  const AnalyticDomain d = layers({{{Vec3::Constant(-2), Vec3::Constant(3)}, 1},
                                   {{Vec3(0.4, -2, -2), Vec3(3, 0.55, 3)}, 2},
                                   {{Vec3(0.4, 0.55, -2), Vec3::Constant(3)}, 3}});
  const test::UnitCube cube = test::unit_cube(d);
  int face_points = 0;
  for (const auto& f : cube.faces) face_points += f.kind == cutcell::FacePointKind::interface_point;
  EXPECT_EQ(face_points, 2);  // z- and z+, joined by the triple line
  const CellSplit split = cutcell::split_cell(cube.input);
  EXPECT_EQ(split.pieces.size(), 3u);
  const auto v = region_volumes(cube, split);
  EXPECT_NEAR(v.at(1), 0.4, 1e-12);
  EXPECT_NEAR(v.at(2), 0.6 * 0.55, 1e-12);
  EXPECT_NEAR(v.at(3), 0.6 * 0.45, 1e-12);
}

TEST(CellSplit, FourRegionsAroundALine) {
  const AnalyticDomain d = layers({{{Vec3::Constant(-2), Vec3::Constant(3)}, 1},
                                   {{Vec3(0.35, -2, -2), Vec3(3, 0.6, 3)}, 2},
                                   {{Vec3(0.35, 0.6, -2), Vec3::Constant(3)}, 3},
                                   {{Vec3(-2, 0.6, -2), Vec3(0.35, 3, 3)}, 4}});
  const test::UnitCube cube = test::unit_cube(d);
  const CellSplit split = cutcell::split_cell(cube.input);
  EXPECT_EQ(split.pieces.size(), 4u);
  const auto v = region_volumes(cube, split);
  EXPECT_NEAR(v.at(1), 0.35 * 0.6, 1e-12);
  EXPECT_NEAR(v.at(3), 0.65 * 0.4, 1e-12);
}

TEST(CellSplit, JunctionPointInsideTheCellIsTheCellInterfacePoint) {
  // Four regions meeting at (0.4, 0.45, 0.55): more than two face interface points.
  const AnalyticDomain d = layers({{{Vec3::Constant(-2), Vec3::Constant(3)}, 1},
                                   {{Vec3(0.4, -2, -2), Vec3(3, 0.45, 3)}, 2},
                                   {{Vec3(0.4, 0.45, -2), Vec3(3, 3, 0.55)}, 3},
                                   {{Vec3(0.4, 0.45, 0.55), Vec3::Constant(3)}, 4}});
  const test::UnitCube cube = test::unit_cube(d);
  const CellSplit split = cutcell::split_cell(cube.input);
  EXPECT_FALSE(split.cell_point_left_cell);
  bool fanned = false;
  for (LoopMethod m : split.loops) fanned = fanned || m == LoopMethod::interface_fan;
  EXPECT_TRUE(fanned);
  ASSERT_FALSE(split.new_points.empty());
  EXPECT_LT((split.new_points[0] - Vec3(0.4, 0.45, 0.55)).norm(), 1e-12);
  const auto v = region_volumes(cube, split);
  EXPECT_NEAR(v.at(1), 0.4, 1e-12);
  EXPECT_NEAR(v.at(2), 0.6 * 0.45, 1e-12);
  EXPECT_NEAR(v.at(3), 0.6 * 0.55 * 0.55, 1e-12);
  EXPECT_NEAR(v.at(4), 0.6 * 0.55 * 0.45, 1e-12);
}

// Region 2's edge (x = 0.4, z = 0.55) ends on region 3's plane y = 0.45 inside the cell, as
// builtin:primitives' box edge ends on the cylinder's cap: two face interface points (x+
// and z+), whose link in the plane would cut the edge's end off. The junction is the
// corner, and every component fans around it.
TEST(CellSplit, InteriorEdgeEndingOnAPlaneKeepsItsCorner) {
  const AnalyticDomain d = layers({{{Vec3::Constant(-2), Vec3::Constant(3)}, 1},
                                   {{Vec3(0.4, -2, 0.55), Vec3(3, 0.45, 3)}, 2},
                                   {{Vec3(-2, 0.45, -2), Vec3::Constant(3)}, 3}});
  const test::UnitCube cube = test::unit_cube(d);
  const CellSplit split = cutcell::split_cell(cube.input);
  ASSERT_FALSE(split.new_points.empty());
  EXPECT_LT((split.new_points[0] - Vec3(0.4, 0.45, 0.55)).norm(), 1e-12);
  const auto v = region_volumes(cube, split);
  EXPECT_NEAR(v.at(2), 0.6 * 0.45 * 0.45, 1e-12);
  EXPECT_NEAR(v.at(3), 0.55, 1e-12);
}

TEST(CellSplit, PublishedM3CUsesTheCellCentre) {
  const AnalyticDomain d = layers({{{Vec3::Constant(-2), Vec3::Constant(3)}, 1},
                                   {{Vec3(0.4, -2, -2), Vec3(3, 0.45, 3)}, 2},
                                   {{Vec3(0.4, 0.45, -2), Vec3(3, 3, 0.55)}, 3},
                                   {{Vec3(0.4, 0.45, 0.55), Vec3::Constant(3)}, 4}});
  cutcell::FaceContourOptions face;
  face.exact_points = false;
  cutcell::CellOptions cell;
  cell.exact_points = false;
  const test::UnitCube cube = test::unit_cube(d, face);
  const CellSplit split = cutcell::split_cell(cube.input, cell);
  ASSERT_FALSE(split.new_points.empty());
  EXPECT_LT((split.new_points[0] - Vec3::Constant(0.5)).norm(), 1e-12);
  region_volumes(cube, split);  // closed pieces filling the cube
}

// A junction point just outside the unit cube's face y = 1 slides along its line into the
// cube, to the margin, and not across the other faces: the least move either way.
TEST(SlideIntoCell, MovesAlongTheLineToTheMargin) {
  std::array<Vec3, 8> corners;
  for (int k = 0; k < 8; ++k) corners[k] = test::cube_corner(k);
  const Vec3 line = Vec3(0.0, 1.0, -1.0).normalized();
  const std::optional<Vec3> p = cutcell::slide_into_cell(corners, Vec3(0.5, 1.05, 0.5), line, 0.1, 0.5);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->y(), 0.9, 1e-12);
  EXPECT_NEAR(p->z(), 0.65, 1e-12);
  EXPECT_NEAR(p->x(), 0.5, 1e-12);
  // Along x the face y = 1 stays where it is: no move gets in.
  EXPECT_FALSE(cutcell::slide_into_cell(corners, Vec3(0.5, 1.05, 0.5), Vec3::UnitX(), 0.1, 0.5));
  // Farther than reach.
  EXPECT_FALSE(cutcell::slide_into_cell(corners, Vec3(0.5, 1.05, 0.5), line, 0.1, 0.1));
}

TEST(MergeAlongEdge, JoinsTwoFacesAcrossTheirOneSharedEdge) {
  // (0 1 2) and (2 1 3) share 1 -> 2 / 2 -> 1: the quad keeps the orientation of both.
  EXPECT_EQ(cutcell::merge_along_edge({0, 1, 2}, {2, 1, 3}), (std::vector<int>{2, 0, 1, 3}));
  EXPECT_TRUE(cutcell::merge_along_edge({0, 1, 2}, {3, 4, 5}).empty());  // no shared edge
  EXPECT_TRUE(cutcell::merge_along_edge({0, 1, 2}, {1, 2, 3}).empty());  // same direction: not adjacent
  // Sharing 1 -> 2 but also touching at 4: the union would pass through 4 twice.
  EXPECT_TRUE(cutcell::merge_along_edge({0, 1, 2, 4}, {2, 1, 4, 5}).empty());
}

}  // namespace
}  // namespace volmesh
