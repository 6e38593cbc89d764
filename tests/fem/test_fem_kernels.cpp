// Quadrature rules integrate every monomial of their degree exactly; shape functions are
// nodal and sum to one; the polyhedral sub-tessellation fills each cell exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/unit_cube_meshes.hpp"
#include "fem_test_meshes.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/fem/lagrange.hpp"
#include "volmesh/fem/polyhedral.hpp"
#include "volmesh/fem/quadrature.hpp"

namespace volmesh::fem {
namespace {

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

TEST(Quadrature, TetRulesIntegrateMonomialsOfTheirDegree) {
  // ∫ over the unit simplex of x^a y^b z^c = a! b! c! / (a+b+c+3)!.
  for (int degree : {1, 2, 5}) {
    const auto rule = tet_rule(degree);
    double sum = 0.0;
    for (const auto& q : rule) {
      EXPECT_GT(q.weight, 0.0);
      sum += q.weight;
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; a + b <= degree; ++b)
        for (int c = 0; a + b + c <= degree; ++c) {
          double integral = 0.0;
          for (const auto& q : rule) {
            const auto& l = q.barycentric;
            integral += q.weight / 6.0 * std::pow(l[1], a) * std::pow(l[2], b) * std::pow(l[3], c);
          }
          const double exact =
              factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + 3);
          EXPECT_NEAR(integral, exact, 1e-15) << "degree " << degree << ": " << a << b << c;
        }
  }
  // Degree 6 is beyond the 14-point rule: it must show.
  double integral = 0.0;
  for (const auto& q : tet_rule(5)) integral += q.weight / 6.0 * std::pow(q.barycentric[1], 6);
  EXPECT_GT(std::abs(integral - factorial(6) / factorial(9)), 1e-8);
}

TEST(Quadrature, TriangleRulesIntegrateMonomialsOfTheirDegree) {
  for (int degree : {1, 2, 5}) {
    const auto rule = triangle_rule(degree);
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; a + b <= degree; ++b) {
        double integral = 0.0;
        for (const auto& q : rule)
          integral +=
              q.weight / 2.0 * std::pow(q.barycentric[1], a) * std::pow(q.barycentric[2], b);
        EXPECT_NEAR(integral, factorial(a) * factorial(b) / factorial(a + b + 2), 1e-14)
            << "degree " << degree << ": " << a << b;
      }
  }
}

TEST(Quadrature, GaussLegendreIsExactToDegreeTwoNMinusOne) {
  for (int n = 1; n <= 4; ++n)
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double integral = 0.0;
      for (const auto& q : gauss_legendre(n)) integral += q.weight * std::pow(q.x, k);
      EXPECT_NEAR(integral, k % 2 ? 0.0 : 2.0 / (k + 1), 1e-15) << n << " points, x^" << k;
    }
}

TEST(Lagrange, P1GradientsReproduceALinearFunction) {
  const Vec3 a(0.1, 0.2, 0.0), b(1.3, 0.1, 0.2), c(0.2, 1.1, -0.1), d(0.3, 0.4, 0.9);
  const TetAffine t = tet_affine(a, b, c, d);
  EXPECT_NEAR(t.volume, tet_volume(a, b, c, d), 1e-15);
  const Vec3 g(2.0, -1.0, 0.5);
  const Vec3 grad = a.dot(g) * t.gradient[0] + b.dot(g) * t.gradient[1] + c.dot(g) * t.gradient[2] +
                    d.dot(g) * t.gradient[3];
  EXPECT_LT((grad - g).norm(), 1e-13);
}

TEST(Lagrange, P2IsNodalAndItsGradientsSumToZero) {
  // Barycentric coordinates of the 10 nodes.
  std::array<std::array<double, 4>, 10> nodes{};
  for (int i = 0; i < 4; ++i) nodes[i][i] = 1.0;
  for (int e = 0; e < 6; ++e) nodes[4 + e][kTetEdges[e][0]] = nodes[4 + e][kTetEdges[e][1]] = 0.5;
  const TetAffine t = tet_affine(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
  for (int k = 0; k < 10; ++k) {
    std::array<double, 10> n;
    p2_tet_values(nodes[k], n);
    for (int j = 0; j < 10; ++j) EXPECT_NEAR(n[j], j == k ? 1.0 : 0.0, 1e-15);
    std::array<Vec3, 10> g;
    p2_tet_gradients(nodes[k], t.gradient, g);
    Vec3 sum = Vec3::Zero();
    for (const Vec3& v : g) sum += v;
    EXPECT_LT(sum.norm(), 1e-14);
  }
  std::array<double, 6> n;
  p2_triangle_values({0.5, 0.0, 0.5}, n);  // the midpoint of edge (2, 0)
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(n[j], j == 5 ? 1.0 : 0.0, 1e-15);
}

TEST(Lagrange, Q1IsNodalAndSumsToOne) {
  for (int k = 0; k < 8; ++k) {
    std::array<double, 8> n;
    q1_hex_values(Vec3(kHexCorners[k][0], kHexCorners[k][1], kHexCorners[k][2]), n);
    for (int j = 0; j < 8; ++j) EXPECT_EQ(n[j], j == k ? 1.0 : 0.0);
  }
  std::array<double, 8> n;
  std::array<Vec3, 8> g;
  const Vec3 xi(0.3, -0.7, 0.1);
  q1_hex_values(xi, n);
  q1_hex_reference_gradients(xi, g);
  double sum = 0.0;
  Vec3 gsum = Vec3::Zero(), x_gradient = Vec3::Zero();
  for (int a = 0; a < 8; ++a) {
    sum += n[a];
    gsum += g[a];
    x_gradient += kHexCorners[a][0] * g[a];  // ∇ξ of ξ itself
  }
  EXPECT_NEAR(sum, 1.0, 1e-15);
  EXPECT_LT(gsum.norm(), 1e-15);
  EXPECT_LT((x_gradient - Vec3(1, 0, 0)).norm(), 1e-15);
}

// The sub-tetrahedra of every cell are positive and add up to the cell volume that core's
// geometry computes, for octree cells with hanging faces and warped cut cells; those cells
// are star-shaped about their vertex average.
TEST(Polyhedral, SubTetrahedraFillEachCell) {
  std::vector<PolyMesh> meshes{test::big_cube_next_to_four_small(), test::octree_checkerboard(2),
                               test::plane_cut_grid(3, Vec3(1.0, 0.6, 0.35), 0.93)};
  test::warp(meshes.back(), 0.04);
  for (const PolyMesh& mesh : meshes) {
    const CellFaces cf = build_cell_faces(mesh);
    const MeshGeometry geometry = mesh_geometry(mesh, cf);
    const FaceSplits splits = split_faces(mesh);
    EXPECT_TRUE(splits.triangles.empty());  // every fan is proper
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const auto apex = star_centre(mesh, splits, cf.of(c), c);
      ASSERT_TRUE(apex);
      Vec3 average = Vec3::Zero();
      int vertices = 0;
      for (Index p = 0; p < mesh.num_points(); ++p)
        for (Index f : cf.of(c))
          if (std::find(mesh.face(f).begin(), mesh.face(f).end(), p) != mesh.face(f).end()) {
            average += mesh.points[p];
            ++vertices;
            break;
          }
      EXPECT_LT((*apex - average / vertices).norm(), 1e-15);
      double volume = 0.0;
      int count = 0;
      for_each_sub_tetrahedron(mesh, splits, cf.of(c), c, *apex, [&](const SubTetrahedron& t) {
        const double v = tet_volume(t.corners[0], t.corners[1], t.corners[2], t.corners[3]);
        EXPECT_GT(v, 0.0) << "cell " << c << " face " << t.face;
        volume += v;
        ++count;
      });
      EXPECT_NEAR(volume, geometry.cells[c].volume, 1e-14) << "cell " << c;
      EXPECT_GE(count, 4);
    }
  }
}

// An L-shaped prism with a long arm: its two L faces fold their fans about the vertex
// average, and the cell is not star-shaped about its vertex average either. The faces are
// ear-clipped, the apex moves into the kernel, and the sub-tetrahedra fill the cell.
TEST(Polyhedral, NonConvexFacesAndCellsFindATriangulationAndACentre) {
  const PolyMesh mesh = test::l_prism_stack(1);
  const Index n = 6;
  const FaceSplits splits = split_faces(mesh);
  EXPECT_FALSE(splits.fanned(mesh, 0));
  EXPECT_FALSE(splits.fanned(mesh, 1));
  EXPECT_EQ(splits.offsets[2] - splits.offsets[0], 2 * (n - 2));
  for (Index f = 2; f < mesh.num_faces(); ++f) EXPECT_TRUE(splits.fanned(mesh, f));
  const CellFaces cf = build_cell_faces(mesh);
  const auto apex = star_centre(mesh, splits, cf.of(0), 0);
  ASSERT_TRUE(apex);
  // Not the vertex average (14/6, 14/6, 1/2), outside the L; the kernel is [0,1]² × [0,1].
  EXPECT_LT(apex->x(), 1.0);
  EXPECT_LT(apex->y(), 1.0);
  double volume = 0.0;
  for_each_sub_tetrahedron(mesh, splits, cf.of(0), 0, *apex, [&](const SubTetrahedron& t) {
    const double v = tet_volume(t.corners[0], t.corners[1], t.corners[2], t.corners[3]);
    EXPECT_GT(v, 0.0) << "face " << t.face;
    volume += v;
  });
  EXPECT_NEAR(volume, 11.0, 1e-12);  // (6 + 5) × 1 × height 1
}

// A U-shaped prism with long arms has no star centre. Its virtual element has the cell's
// volume and centroid, and a projection that reproduces linear functions:
// Σ_i x_i g_iᵀ = I and Σ_i g_i = 0.
TEST(Polyhedral, AUShapedPrismIsAVirtualElement) {
  const PolyMesh mesh = test::u_prism_stack(1);
  const FaceSplits splits = split_faces(mesh);
  const CellFaces cf = build_cell_faces(mesh);
  EXPECT_FALSE(star_centre(mesh, splits, cf.of(0), 0));
  std::vector<Index> vertices(mesh.num_points());
  for (Index v = 0; v < mesh.num_points(); ++v) vertices[v] = v;
  const auto e = virtual_element(mesh, splits, cf.of(0), 0, vertices);
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->volume, 13.0, 1e-12);  // 5 × 1 + 2 arms × 4 × 1, height 1
  // Centroid: the bar [0,5]×[0,1] and the arms [0,1]×[1,5], [4,5]×[1,5], all at z = 1/2.
  EXPECT_LT((e->centroid - Vec3((5 * 2.5 + 4 * 0.5 + 4 * 4.5) / 13.0,
                                (5 * 0.5 + 4 * 3.0 + 4 * 3.0) / 13.0, 0.5))
                .norm(),
            1e-12);
  Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
  Vec3 sum = Vec3::Zero();
  for (Index v = 0; v < mesh.num_points(); ++v) {
    moment += mesh.points[v] * e->gradient[v].transpose();
    sum += e->gradient[v];
  }
  EXPECT_LT((moment - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_LT(sum.norm(), 1e-12);
}

}  // namespace
}  // namespace volmesh::fem
