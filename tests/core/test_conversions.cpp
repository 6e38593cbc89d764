#include <gtest/gtest.h>

#include "../support/unit_cube_meshes.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/core/validity.hpp"

namespace volmesh {
namespace {

void expect_valid_unit_volume(const PolyMesh& mesh, double volume = 1.0) {
  const ValidityReport r = check_validity(mesh);
  EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
  EXPECT_EQ(r.open_cells, 0);
  EXPECT_EQ(r.non_positive_cells, 0);
  EXPECT_NEAR(r.total_volume, volume, 1e-14);
  EXPECT_LT(r.max_closedness, 1e-14);
}

TEST(Conversions, UnitCubeIn5TetsIsClosedWithVolumeOne) {
  const PolyMesh p = to_poly_mesh(test::unit_cube_5_tets());
  EXPECT_EQ(p.num_faces(), 4 + 12);  // 4 internal, 2 triangles on each side
  expect_valid_unit_volume(p);
}

TEST(Conversions, UnitCubeIn6KuhnTetsIsClosedWithVolumeOne) {
  const TetMesh t = kuhn_tet_mesh(Vec3::Zero(), Vec3::Ones(), {1, 1, 1});
  ASSERT_EQ(t.num_cells(), 6);
  EXPECT_EQ(t.boundary_faces.size(), 12u);
  const PolyMesh p = to_poly_mesh(t);
  expect_valid_unit_volume(p);
  for (Index f = 0; f < p.num_faces(); ++f)
    if (p.is_boundary(f)) {
      EXPECT_NE(p.tag_names[p.face_tag[f]], "boundary");
    }
}

TEST(Conversions, UnitCubeIn24TetsIsClosedWithVolumeOne) {
  expect_valid_unit_volume(to_poly_mesh(test::unit_cube_24_tets()));
}

TEST(Conversions, UnitCubeAsOneAndEightHexes) {
  expect_valid_unit_volume(to_poly_mesh(test::unit_cube_hex()));
  const HexMesh eight = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2});
  const PolyMesh p = to_poly_mesh(eight);
  EXPECT_EQ(p.num_faces(), 12 + 24);
  expect_valid_unit_volume(p);
}

TEST(Conversions, KuhnGridIsConforming) {
  const PolyMesh p = to_poly_mesh(kuhn_tet_mesh(Vec3(-1, 0, 2), Vec3(1, 3, 3), {3, 2, 4}));
  EXPECT_EQ(p.num_cells(), 6 * 24);
  expect_valid_unit_volume(p, 6.0);
}

TEST(Conversions, RoundTripsRecoverTheSameElements) {
  const TetMesh tets = kuhn_tet_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2});
  const TetMesh back = to_tet_mesh(to_poly_mesh(tets));
  ASSERT_EQ(back.num_cells(), tets.num_cells());
  for (Index c = 0; c < tets.num_cells(); ++c) {
    auto a = tets.cells[c], b = back.cells[c];
    // Same vertex set and same orientation (an even permutation).
    const double va = tet_volume(tets.points[a[0]], tets.points[a[1]], tets.points[a[2]], tets.points[a[3]]);
    const double vb = tet_volume(back.points[b[0]], back.points[b[1]], back.points[b[2]], back.points[b[3]]);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b);
    EXPECT_DOUBLE_EQ(va, vb);
  }
  EXPECT_EQ(back.boundary_faces.size(), tets.boundary_faces.size());

  const HexMesh hexes = structured_hex_mesh(Vec3::Zero(), Vec3(1, 2, 3), {2, 3, 1});
  const HexMesh hback = to_hex_mesh(to_poly_mesh(hexes));
  ASSERT_EQ(hback.num_cells(), hexes.num_cells());
  for (Index c = 0; c < hexes.num_cells(); ++c) {
    // Corner order may start elsewhere, but the hex must be the same positive cell.
    const PolyMesh single = to_poly_mesh(HexMesh{hback.points, {hback.cells[c]}, {1}, {}, {}, {}});
    EXPECT_NEAR(check_validity(single).total_volume, 1.0, 1e-12);
  }
}

TEST(Conversions, PolyhedronIsNotATet) {
  const PolyMesh p = test::big_cube_next_to_four_small();
  EXPECT_THROW(to_tet_mesh(p), InputError);
  EXPECT_THROW(to_hex_mesh(p), InputError);
  const CellFaces cf = build_cell_faces(p);
  EXPECT_EQ(classify_cell(p, cf, 0).shape, CellShape::Polyhedron);
  EXPECT_EQ(classify_cell(p, cf, 1).shape, CellShape::Hexahedron);
}

TEST(Conversions, InvertedInteriorTetIsRefused) {
  // The central tet's faces are all owned by corner tets: its reversed vertex order shows
  // only as a shared face that both cells orient alike.
  TetMesh t = test::unit_cube_5_tets();
  std::swap(t.cells[4][1], t.cells[4][2]);
  try {
    to_poly_mesh(t);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("inverted"), std::string::npos) << e.what();
  }
}

TEST(Conversions, FaceSharedByThreeCellsIsRefused) {
  TetMesh t;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1}};
  t.cells = {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}};
  t.cell_region = {1, 1, 1};
  EXPECT_THROW(to_poly_mesh(t), InputError);
}

}  // namespace
}  // namespace volmesh
