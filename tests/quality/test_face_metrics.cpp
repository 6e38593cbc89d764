#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "../support/unit_cube_meshes.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/quality/face_metrics.hpp"

namespace volmesh {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

struct Measured {
  PolyMesh mesh;
  MeshGeometry geometry;
  std::vector<double> non_orthogonality, skewness, volume_ratio;

  explicit Measured(PolyMesh m) : mesh(std::move(m)) {
    geometry = mesh_geometry(mesh, build_cell_faces(mesh));
    non_orthogonality = face_non_orthogonality(mesh, geometry);
    skewness = face_skewness(mesh, geometry);
    volume_ratio = face_volume_ratio(mesh, geometry);
  }
  Index face_at(const Vec3& centre) const {
    for (Index f = 0; f < mesh.num_faces(); ++f)
      if ((geometry.faces[f].centre - centre).norm() < 1e-12) return f;
    ADD_FAILURE() << "no face centred at " << centre.transpose();
    return 0;
  }
};

TEST(FaceMetrics, CubeGridIsOrthogonalAndUnskewed) {
  const Measured m(to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2})));
  ASSERT_EQ(m.mesh.num_faces(), 36);
  for (Index f = 0; f < m.mesh.num_faces(); ++f) {
    EXPECT_NEAR(m.non_orthogonality[f], 0.0, 1e-12) << "face " << f;
    EXPECT_NEAR(m.skewness[f], 0.0, 1e-12) << "face " << f;
    if (m.mesh.is_boundary(f))
      EXPECT_TRUE(std::isnan(m.volume_ratio[f]));
    else
      EXPECT_NEAR(m.volume_ratio[f], 1.0, 1e-12);
  }
}

// The unit cube A = [0,1]³ and, across its face x = 1, the parallelepiped B whose far face
// is shifted by +1 in y: B's centre is (1.5, 1, 0.5). All faces are planar, so every face
// and cell centre is an exact centroid and OpenFOAM's values can be worked out by hand.
PolyMesh cube_and_sheared_neighbour() {
  HexMesh h;
  h.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
              {1, 1, 1}, {0, 1, 1}, {2, 1, 0}, {2, 2, 0}, {2, 1, 1}, {2, 2, 1}};
  h.cells = {{0, 1, 2, 3, 4, 5, 6, 7}, {1, 8, 9, 2, 5, 10, 11, 6}};
  h.cell_region = {1, 1};
  return to_poly_mesh(h);
}

TEST(FaceMetrics, ShearedNeighbourMatchesHandComputedOpenFoamValues) {
  const Measured m(cube_and_sheared_neighbour());
  // Shared face x = 1: area (1,0,0), d = (1, 0.5, 0) → non-orthogonality atan(1/2).
  // Skewness vector Cpf - (S·Cpf / S·d)·d = (0.5,0,0) - 0.5·(1,0.5,0) = (0,-0.25,0); the face
  // extends 0.5 along y (> 0.2·|d|), so skewness = 0.25 / 0.5.
  const Index shared = m.face_at({1, 0.5, 0.5});
  ASSERT_FALSE(m.mesh.is_boundary(shared));
  EXPECT_NEAR(m.non_orthogonality[shared], std::atan(0.5) * kDeg, 1e-12);
  EXPECT_NEAR(m.non_orthogonality[shared], 26.565051177, 1e-8);
  EXPECT_NEAR(m.skewness[shared], 0.5, 1e-14);
  EXPECT_NEAR(m.volume_ratio[shared], 1.0, 1e-14);

  // B's slanted side y = x - 1: owner → face centre (0,-0.5,0) at 45° to the normal
  // (1,-1,0)/sqrt 2; d = its normal part (0.25,-0.25,0), sv = (-0.25,-0.25,0) of length
  // sqrt(2)/4, over the face's extent sqrt(2)/2 along sv: 0.5.
  for (const Vec3& centre : {Vec3(1.5, 0.5, 0.5), Vec3(1.5, 1.5, 0.5)}) {
    const Index f = m.face_at(centre);
    ASSERT_TRUE(m.mesh.is_boundary(f));
    EXPECT_NEAR(m.non_orthogonality[f], 45.0, 1e-12);
    EXPECT_NEAR(m.skewness[f], 0.5, 1e-14);
  }
  // B's far face x = 2, centred at (2, 1.5, 0.5): Cpf = (0.5,0.5,0), sv = (0,0.5,0) against
  // an extent of 0.5 (> 0.4·|d| = 0.2): skewness 1.
  const Index far = m.face_at({2, 1.5, 0.5});
  EXPECT_NEAR(m.non_orthogonality[far], 45.0, 1e-12);
  EXPECT_NEAR(m.skewness[far], 1.0, 1e-14);
  // A's own boundary faces and B's top and bottom are centred over their cell.
  for (const Vec3& centre :
       {Vec3(0, 0.5, 0.5), Vec3(0.5, 0, 0.5), Vec3(0.5, 0.5, 1), Vec3(1.5, 1, 0)}) {
    const Index f = m.face_at(centre);
    EXPECT_NEAR(m.non_orthogonality[f], 0.0, 1e-12);
    EXPECT_NEAR(m.skewness[f], 0.0, 1e-14);
  }
}

TEST(FaceMetrics, OctreeTransitionMatchesHandComputedOpenFoamValues) {
  const Measured m(test::big_cube_next_to_four_small());
  // Big cell centre (0.5,0.5,0.5) to a small one, e.g. (1.25,0.25,0.25): d = (0.75,-0.25,-0.25),
  // cos = 0.75/|d| = 3/sqrt(11). Cpf = (0.5,-0.25,-0.25), sv = Cpf - (2/3)d = (0,-1,-1)/12,
  // extent along sv 0.25·sqrt(2) → skewness (sqrt(2)/12) / (sqrt(2)/4) = 1/3.
  int transition = 0;
  for (Index f = 0; f < m.mesh.num_faces(); ++f) {
    if (m.mesh.is_boundary(f)) {
      EXPECT_NEAR(m.non_orthogonality[f], 0.0, 1e-12);
      EXPECT_NEAR(m.skewness[f], 0.0, 1e-14);
    } else if (m.mesh.owner[f] == 0) {
      ++transition;
      EXPECT_NEAR(m.non_orthogonality[f], std::acos(3.0 / std::sqrt(11.0)) * kDeg, 1e-12);
      EXPECT_NEAR(m.skewness[f], 1.0 / 3.0, 1e-14);
      EXPECT_NEAR(m.volume_ratio[f], 8.0, 1e-13);
    } else {  // between two small cubes
      EXPECT_NEAR(m.non_orthogonality[f], 0.0, 1e-12);
      EXPECT_NEAR(m.skewness[f], 0.0, 1e-14);
      EXPECT_NEAR(m.volume_ratio[f], 1.0, 1e-13);
    }
  }
  EXPECT_EQ(transition, 4);
}

TEST(FaceMetrics, ReversedNeighbourIsBeyondNinetyDegrees) {
  // Swapping the two cells of the sheared pair without reorienting the shared face makes
  // its area vector point back at the owner: the angle becomes 180° - atan(1/2).
  PolyMesh p = cube_and_sheared_neighbour();
  const Measured before(p);
  const Index shared = before.face_at({1, 0.5, 0.5});
  std::swap(p.owner[shared], p.neighbour[shared]);
  MeshGeometry g = before.geometry;
  EXPECT_NEAR(face_non_orthogonality(p, g)[shared], 180.0 - std::atan(0.5) * kDeg, 1e-12);
}

TEST(FaceMetrics, APyramidIsInvertedWhereACellCentreLiesBehindItsFace) {
  const Measured right(cube_and_sheared_neighbour());
  for (const std::uint8_t inverted : face_inverted_pyramids(right.mesh, build_cell_faces(right.mesh), right.geometry))
    EXPECT_EQ(inverted, 0);
  // The shared face pointing back at its owner: both centres lie behind it, two pyramids.
  PolyMesh p = cube_and_sheared_neighbour();
  const Index shared = right.face_at({1, 0.5, 0.5});
  std::swap(p.owner[shared], p.neighbour[shared]);
  const std::vector<std::uint8_t> inverted = face_inverted_pyramids(p, build_cell_faces(p), right.geometry);
  for (Index f = 0; f < p.num_faces(); ++f) EXPECT_EQ(inverted[f], f == shared ? 2 : 0) << f;
}

// The screen the mesher's merging uses to skip the exact verdict: whatever it passes, the
// verdict passes too. Jittered grids, from mild to folded, give faces on both sides.
TEST(FaceMetrics, FacesSurelyWithinTheLimitsAreWithinThem) {
  const CheckMeshLimits limits;
  std::mt19937 random(7);
  Index screened = 0, beyond = 0, exact = 0;
  for (const double jitter : {0.0, 0.2, 0.5, 0.9, 1.3}) {
    HexMesh h = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {6, 6, 6});
    std::uniform_real_distribution<double> offset(-jitter / 6.0, jitter / 6.0);
    for (Vec3& p : h.points) p += Vec3(offset(random), offset(random), offset(random));
    const Measured m(to_poly_mesh(h));
    for (Index f = 0; f < m.mesh.num_faces(); ++f) {
      const FaceGeometry& g = m.geometry.faces[f];
      const Vec3& owner = m.geometry.cells[m.mesh.owner[f]].centre;
      const Vec3* neighbour = m.mesh.is_boundary(f) ? nullptr : &m.geometry.cells[m.mesh.neighbour[f]].centre;
      const double badness = checkmesh_badness(g, m.mesh.points, m.mesh.face(f), owner, neighbour, limits);
      beyond += badness > 1.0;
      if (!surely_within_checkmesh_limits(g, owner, neighbour, limits)) {
        EXPECT_NE(jitter, 0.0) << "a face of the regular grid left to the exact verdict";
        ++exact;
        continue;
      }
      ++screened;
      EXPECT_LE(badness, 1.0) << "jitter " << jitter << ", face " << f;
    }
  }
  EXPECT_GT(beyond, 300);     // 408 of 3,780
  EXPECT_GT(screened, 3000);  // 3,226: the screen spares most faces the vertex loop
}

}  // namespace
}  // namespace volmesh
