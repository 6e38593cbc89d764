// The conforming tet decomposition: valid tetrahedra only, the same volume in every region,
// no hanging nodes (every tet face is shared with another tet or lies on the original
// boundary with its tag), for cubes, octree cells with hanging sides and non-convex cut cells;
// a cell that no point sees whole is refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>

#include "../fem/fem_test_meshes.hpp"
#include "../support/unit_cube_meshes.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/geometry/cell_tessellation.hpp"
#include "volmesh/geometry/tet_decomposition.hpp"

namespace volmesh {
namespace {

constexpr double kVolumeTolerance = 1e-12;

// Boundary area per tag name.
std::map<std::string, double> boundary_areas(const PolyMesh& mesh) {
  std::map<std::string, double> areas;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (mesh.is_boundary(f))
      areas[mesh.tag_names[mesh.face_tag[f]]] += face_geometry(mesh, f).area_vector.norm();
  return areas;
}

// The triangles the boundary faces of `mesh` split into.
Index boundary_triangles(const PolyMesh& mesh) {
  const FaceSplits splits = split_faces(mesh);
  Index count = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!mesh.is_boundary(f)) continue;
    const auto n = static_cast<Index>(mesh.face(f).size());
    count += n == 3 ? 1 : splits.fanned(mesh, f) ? n : splits.offsets[f + 1] - splits.offsets[f];
  }
  return count;
}

// Decomposes `mesh` and checks every property the decomposition promises; returns the tets.
PolyMesh expect_conforming_decomposition(const PolyMesh& mesh) {
  const ValidityReport before = check_validity(mesh);
  EXPECT_TRUE(before.valid());
  const PolyMesh tets = decompose_into_tets(mesh);
  const ValidityReport after = check_validity(tets);
  EXPECT_TRUE(after.valid()) << (after.problems.empty() ? "" : after.problems.front());
  EXPECT_GT(after.min_cell_volume, 0.0);

  const CellFaces cell_faces = build_cell_faces(tets);
  for (Index c = 0; c < tets.num_cells(); ++c)
    EXPECT_EQ(classify_cell(tets, cell_faces, c).shape, CellShape::Tetrahedron) << "cell " << c;

  // Conforming: each tet face is one mesh face, shared with one other tet or on the boundary,
  // and the boundary faces are exactly the triangles of the original boundary faces.
  Index boundary = 0;
  for (Index f = 0; f < tets.num_faces(); ++f) {
    EXPECT_EQ(tets.face(f).size(), 3u);
    boundary += tets.is_boundary(f);
  }
  EXPECT_EQ(4 * tets.num_cells(), 2 * (tets.num_faces() - boundary) + boundary);
  EXPECT_EQ(boundary, boundary_triangles(mesh));
  EXPECT_EQ(tets.tag_names, mesh.tag_names);
  const auto areas_before = boundary_areas(mesh), areas_after = boundary_areas(tets);
  EXPECT_EQ(areas_after.size(), areas_before.size());
  for (const auto& [tag, area] : areas_before)
    EXPECT_NEAR(areas_after.count(tag) ? areas_after.at(tag) : 0.0, area, kVolumeTolerance) << tag;

  // Volumes, in all and per region; the mesh's points keep their indices.
  EXPECT_NEAR(after.total_volume, before.total_volume, kVolumeTolerance);
  EXPECT_EQ(after.region_volume.size(), before.region_volume.size());
  for (const auto& [region, volume] : before.region_volume)
    EXPECT_NEAR(after.region_volume.count(region) ? after.region_volume.at(region) : 0.0, volume,
                kVolumeTolerance)
        << "region " << region;
  EXPECT_TRUE(std::equal(mesh.points.begin(), mesh.points.end(), tets.points.begin()));
  return tets;
}

// A tet as its sorted corner coordinates, to compare decompositions that number points apart.
using TetCorners = std::array<std::array<double, 3>, 4>;
std::vector<TetCorners> tet_corner_sets(const PolyMesh& mesh) {
  const CellFaces cell_faces = build_cell_faces(mesh);
  std::vector<TetCorners> tets;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const CellCorners corners = classify_cell(mesh, cell_faces, c);
    TetCorners t;
    for (int k = 0; k < 4; ++k) {
      const Vec3& p = mesh.points[corners.corners[k]];
      t[k] = {p.x(), p.y(), p.z()};
    }
    std::sort(t.begin(), t.end());
    tets.push_back(t);
  }
  std::sort(tets.begin(), tets.end());
  return tets;
}

// A hex is split like any cell: its faces fanned about their centres, 24 tets about the
// cube's centre.
TEST(TetDecomposition, CubeIsTwentyFourTetsAboutItsCentre) {
  const PolyMesh tets = expect_conforming_decomposition(to_poly_mesh(test::unit_cube_hex()));
  EXPECT_EQ(tets.num_cells(), 24);
  EXPECT_EQ(tets.num_points(), 8 + 6 + 1);
  EXPECT_EQ(tet_corner_sets(tets), tet_corner_sets(to_poly_mesh(test::unit_cube_24_tets())));
}

// Tetrahedra stay whole, with their points and no new ones.
TEST(TetDecomposition, TetrahedraStayWhole) {
  const PolyMesh mesh = test::kuhn_cube(2);
  const PolyMesh tets = expect_conforming_decomposition(mesh);
  EXPECT_EQ(tets.num_cells(), mesh.num_cells());
  EXPECT_EQ(tets.num_points(), mesh.num_points());
  EXPECT_EQ(tet_corner_sets(tets), tet_corner_sets(mesh));
}

// The big cube's side towards four smaller cubes is four faces already; each is fanned alike
// from both sides, and its other faces carry the mid-edge vertices.
TEST(TetDecomposition, OctreeCellWithAHangingSideConforms) {
  const PolyMesh mesh = test::big_cube_next_to_four_small(true);
  const PolyMesh tets = expect_conforming_decomposition(mesh);
  // Big cube: 4 five-vertex faces, 1 four-vertex face and 4 small faces, each fanned: 4×5 +
  // 1×4 + 4×4 = 40 tets; each small cube 24.
  EXPECT_EQ(tets.num_cells(), 40 + 4 * 24);
}

TEST(TetDecomposition, OctreeCheckerboardConforms) {
  expect_conforming_decomposition(test::octree_checkerboard(2));
}

// Cut cells of two regions with warped faces: every fan is proper and the pieces fill each
// cell as core/geometry measures it.
TEST(TetDecomposition, WarpedCutCellsConform) {
  PolyMesh mesh = test::plane_cut_grid(3, Vec3(1.0, 0.6, 0.35), 0.93);
  test::warp(mesh, 0.04);
  expect_conforming_decomposition(mesh);
}

// L-shaped prisms: the L faces fold their fans and are ear-clipped, alike from both prisms
// that share one; the cells' vertex averages lie outside them, so the centres are found in
// their kernels.
TEST(TetDecomposition, NonConvexCutCellsConform) {
  const PolyMesh mesh = test::l_prism_stack(2);
  const PolyMesh tets = expect_conforming_decomposition(mesh);
  // Per prism: 2 L faces of 4 triangles each, 6 quads of 4: 32 tets.
  EXPECT_EQ(tets.num_cells(), 2 * 32);
}

TEST(TetDecomposition, CellThatNoPointSeesWholeIsNamed) {
  try {
    decompose_into_tets(test::u_prism_stack(1), "u.vtu");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "u.vtu: cell 0 (region 1, 10 faces): no point inside sees all its faces; it "
              "cannot be split into tetrahedra about one centre");
  }
}

}  // namespace
}  // namespace volmesh
