// Patch tests: every space reproduces a linear solution to rounding — Poisson (values,
// gradients, cell means) and elasticity (displacements, constant stresses) — on tets, hexes,
// octree cells with hanging faces and warped cut cells, with Dirichlet data everywhere or
// fluxes/tractions on some sides; on stacked L- and U-shaped prisms (non-convex faces and
// cells, the U's with no star centre);
// and a piecewise-linear solution across a material interface the mesh follows.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>

#include "../support/unit_cube_meshes.hpp"
#include "fem_test_meshes.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/fem/fem.hpp"

namespace volmesh::fem {
namespace {

constexpr double kTolerance = 1e-10;

struct PatchCase {
  std::string name;
  std::function<PolyMesh()> mesh;
  Space space;
};

std::ostream& operator<<(std::ostream& os, const PatchCase& c) { return os << c.name; }

PolyMesh warped(PolyMesh mesh, double amplitude) {
  test::warp(mesh, amplitude);
  return mesh;
}

std::vector<PatchCase> patch_cases() {
  return {
      {"P1Kuhn", [] { return test::kuhn_cube(2); }, Space::p1},
      {"P1WarpedKuhn", [] { return warped(test::kuhn_cube(3), 0.05); }, Space::p1},
      {"P1FiveTets", [] { return to_poly_mesh(test::unit_cube_5_tets()); }, Space::p1},
      {"P2Kuhn", [] { return test::kuhn_cube(2); }, Space::p2},
      {"P2WarpedKuhn", [] { return warped(test::kuhn_cube(3), 0.05); }, Space::p2},
      {"Q1Grid", [] { return test::hex_cube(2); }, Space::q1},
      {"Q1WarpedGrid", [] { return warped(test::hex_cube(3), 0.05); }, Space::q1},
      {"PolyhedralTets", [] { return test::kuhn_cube(2); }, Space::polyhedral},
      {"PolyhedralHexes", [] { return warped(test::hex_cube(3), 0.05); }, Space::polyhedral},
      {"PolyhedralBigCubeNextToFourSmall", [] { return test::big_cube_next_to_four_small(); },
       Space::polyhedral},
      {"PolyhedralOctreeCheckerboard", [] { return test::octree_checkerboard(2); },
       Space::polyhedral},
      {"PolyhedralWarpedOctreeCheckerboard",
       [] { return warped(test::octree_checkerboard(2), 0.04); }, Space::polyhedral},
      {"PolyhedralWarpedCutCells",
       [] { return warped(test::plane_cut_grid(3, Vec3(1.0, 0.6, 0.35), 0.93), 0.04); },
       Space::polyhedral},
  };
}

Vec3 side_normal(const std::string& tag) {
  const int axis = tag[0] - 'x';
  Vec3 n = Vec3::Zero();
  n[axis] = tag.substr(1) == "max" ? 1.0 : -1.0;
  return n;
}

bool has_cube_sides(const PolyMesh& mesh) {
  return std::find(mesh.tag_names.begin(), mesh.tag_names.end(), "xmax") != mesh.tag_names.end();
}

class Patch : public ::testing::TestWithParam<PatchCase> {};

TEST_P(Patch, MeshIsValid) {
  const ValidityReport r = check_validity(GetParam().mesh());
  EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
}

// u = 1 + 2x − 3y + z/2 with k = 2.5; Neumann (k ∂u/∂n) on xmax and ymin when the mesh tags
// the cube's sides.
TEST_P(Patch, PoissonReproducesALinearSolution) {
  const PolyMesh mesh = GetParam().mesh();
  const double k = 2.5;
  const Vec3 g(2.0, -3.0, 0.5);
  const auto exact = [g](const Vec3& x) { return 1.0 + g.dot(x); };
  for (bool with_flux : {false, true}) {
    if (with_flux && !has_cube_sides(mesh)) continue;
    PoissonProblem problem;
    for (Index r : regions_of(mesh)) problem.conductivity[r] = k;
    problem.exact = exact;
    problem.exact_gradient = [g](const Vec3&) { return g; };
    for (const std::string& tag : mesh.tag_names) {
      if (with_flux && (tag == "xmax" || tag == "ymin")) {
        const double flux = k * g.dot(side_normal(tag));
        problem.boundary[tag] = {ScalarBoundaryCondition::Kind::neumann,
                                 [flux](const Vec3&) { return flux; }};
      } else {
        problem.boundary[tag] = {ScalarBoundaryCondition::Kind::dirichlet, exact};
      }
    }
    const ScalarSolution s = solve_poisson(mesh, problem, GetParam().space);
    ASSERT_TRUE(s.errors);
    EXPECT_LT(s.errors->l2, kTolerance) << "flux " << with_flux;
    EXPECT_LT(s.errors->linf, kTolerance);
    EXPECT_LT(s.errors->h1, kTolerance);
    for (Index p = 0; p < mesh.num_points(); ++p)
      EXPECT_NEAR(s.point_values[p], exact(mesh.points[p]), kTolerance) << "point " << p;
    // Without an exact solution the means come from the cheaper rule: the same values.
    PoissonProblem plain = problem;
    plain.exact = nullptr;
    plain.exact_gradient = nullptr;
    const ScalarSolution without = solve_poisson(mesh, plain, GetParam().space);
    EXPECT_FALSE(without.errors);
    for (Index c = 0; c < mesh.num_cells(); ++c)
      EXPECT_NEAR(without.cell_values[c], s.cell_values[c], kTolerance) << "cell " << c;
    // Cell means against the value at core's centroid: the same cell as the sub-tessellation
    // (faces fanned about their vertex average); a warped trilinear hex is another cell.
    if (GetParam().space == Space::q1) continue;
    const CellFaces cf = build_cell_faces(mesh);
    const MeshGeometry geometry = mesh_geometry(mesh, cf);
    for (Index c = 0; c < mesh.num_cells(); ++c)
      EXPECT_NEAR(s.cell_values[c], exact(geometry.cells[c].centre), kTolerance) << "cell " << c;
  }
}

// u = A x + c, E = 210, ν = 0.3: the stress is constant; tractions σn on xmax and zmin when
// the mesh tags the cube's sides.
TEST_P(Patch, ElasticityReproducesALinearDisplacement) {
  const PolyMesh mesh = GetParam().mesh();
  Eigen::Matrix3d a;
  a << 0.01, 0.02, -0.03, 0.005, -0.02, 0.01, 0.015, 0.0, 0.025;
  const Vec3 shift(0.1, -0.2, 0.05);
  const auto exact = [a, shift](const Vec3& x) -> Vec3 { return a * x + shift; };
  const IsotropicMaterial steel{210.0, 0.3};
  const Eigen::Matrix3d stress = isotropic_stress(a, lame_parameters(steel));
  for (bool with_traction : {false, true}) {
    if (with_traction && !has_cube_sides(mesh)) continue;
    ElasticityProblem problem;
    for (Index r : regions_of(mesh)) problem.material[r] = steel;
    problem.exact = exact;
    problem.exact_gradient = [a](const Vec3&) { return a; };
    for (const std::string& tag : mesh.tag_names) {
      if (with_traction && (tag == "xmax" || tag == "zmin")) {
        const Vec3 t = stress * side_normal(tag);
        problem.boundary[tag] = {VectorBoundaryCondition::Kind::traction,
                                 [t](const Vec3&) { return t; }};
      } else {
        problem.boundary[tag] = {VectorBoundaryCondition::Kind::displacement, exact};
      }
    }
    const VectorSolution s = solve_elasticity(mesh, problem, GetParam().space);
    ASSERT_TRUE(s.errors);
    EXPECT_LT(s.errors->l2, kTolerance) << "traction " << with_traction;
    EXPECT_LT(s.errors->linf, kTolerance);
    EXPECT_LT(s.errors->h1, kTolerance);
    if (GetParam().space != Space::p2) {
      EXPECT_EQ(s.dofs, 3 * mesh.num_points());
    }
    for (Index p = 0; p < mesh.num_points(); ++p)
      EXPECT_LT((s.point_values[p] - exact(mesh.points[p])).norm(), kTolerance) << "point " << p;
    ElasticityProblem plain = problem;
    plain.exact = nullptr;
    plain.exact_gradient = nullptr;
    const VectorSolution without = solve_elasticity(mesh, plain, GetParam().space);
    EXPECT_FALSE(without.errors);
    const double scale = stress.norm();
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      EXPECT_LT((s.cell_stress[c] - stress).norm(), kTolerance * scale) << "cell " << c;
      EXPECT_LT((without.cell_stress[c] - stress).norm(), kTolerance * scale) << "cell " << c;
      EXPECT_NEAR(s.von_mises[c], von_mises(stress), kTolerance * scale);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Spaces, Patch, ::testing::ValuesIn(patch_cases()),
                         [](const auto& info) { return info.param.name; });

// Two materials, k = 1 and 4, on either side of a plane the cells follow: the exact solution
// is linear on each side, continuous, with continuous flux.
struct Interface {
  Vec3 normal;
  double offset;
  double k1, k2;
  Vec3 g1;
  // u1 = 1 + g1·x below, u2 = u1 + α (normal·x − offset) above.
  double alpha() const { return (k1 - k2) * g1.dot(normal) / (k2 * normal.squaredNorm()); }
  bool above(const Vec3& x) const { return normal.dot(x) > offset; }
  double u(const Vec3& x) const {
    return 1.0 + g1.dot(x) + (above(x) ? alpha() * (normal.dot(x) - offset) : 0.0);
  }
  Vec3 gradient(const Vec3& x) const { return above(x) ? Vec3(g1 + alpha() * normal) : g1; }
};

void expect_interface_reproduced(const PolyMesh& mesh, const Interface& interface) {
  PoissonProblem problem;
  problem.conductivity = {{1, interface.k1}, {2, interface.k2}};
  problem.exact = [&](const Vec3& x) { return interface.u(x); };
  problem.exact_gradient = [&](const Vec3& x) { return interface.gradient(x); };
  for (const std::string& tag : mesh.tag_names)
    problem.boundary[tag] = {ScalarBoundaryCondition::Kind::dirichlet, problem.exact};
  const ScalarSolution s = solve_poisson(mesh, problem, Space::polyhedral);
  ASSERT_TRUE(s.errors);
  EXPECT_LT(s.errors->l2, kTolerance);
  EXPECT_LT(s.errors->linf, kTolerance);
  EXPECT_LT(s.errors->h1, kTolerance);
}

// Dirichlet data on zmin and side0 of stacked prisms, fluxes and tractions elsewhere.
void expect_linear_solutions_on_prisms(const PolyMesh& mesh) {
  EXPECT_TRUE(check_validity(mesh).valid());
  std::map<std::string, Vec3> normal;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (mesh.is_boundary(f))
      normal[mesh.tag_names[mesh.face_tag[f]]] = face_geometry(mesh, f).area_vector.normalized();
  const auto fixed = [](const std::string& tag) { return tag == "zmin" || tag == "side0"; };

  const double k = 2.5;
  const Vec3 g(2.0, -3.0, 0.5);
  PoissonProblem poisson;
  poisson.conductivity[1] = k;
  poisson.exact = [g](const Vec3& x) { return 1.0 + g.dot(x); };
  poisson.exact_gradient = [g](const Vec3&) { return g; };
  for (const auto& [tag, n] : normal) {
    const double flux = k * g.dot(n);
    poisson.boundary[tag] =
        fixed(tag)
            ? ScalarBoundaryCondition{ScalarBoundaryCondition::Kind::dirichlet, poisson.exact}
            : ScalarBoundaryCondition{ScalarBoundaryCondition::Kind::neumann,
                                      [flux](const Vec3&) { return flux; }};
  }
  const ScalarSolution s = solve_poisson(mesh, poisson, Space::polyhedral);
  EXPECT_LT(s.errors->l2, kTolerance);
  EXPECT_LT(s.errors->linf, kTolerance);
  EXPECT_LT(s.errors->h1, kTolerance);

  Eigen::Matrix3d a;
  a << 0.01, 0.02, -0.03, 0.005, -0.02, 0.01, 0.015, 0.0, 0.025;
  const IsotropicMaterial steel{210.0, 0.3};
  const Eigen::Matrix3d stress = isotropic_stress(a, lame_parameters(steel));
  ElasticityProblem elasticity;
  elasticity.material[1] = steel;
  elasticity.exact = [a](const Vec3& x) -> Vec3 { return a * x; };
  elasticity.exact_gradient = [a](const Vec3&) { return a; };
  for (const auto& [tag, n] : normal) {
    const Vec3 t = stress * n;
    elasticity.boundary[tag] =
        fixed(tag)
            ? VectorBoundaryCondition{VectorBoundaryCondition::Kind::displacement, elasticity.exact}
            : VectorBoundaryCondition{VectorBoundaryCondition::Kind::traction,
                                      [t](const Vec3&) { return t; }};
  }
  const VectorSolution v = solve_elasticity(mesh, elasticity, Space::polyhedral);
  EXPECT_LT(v.errors->l2, kTolerance);
  EXPECT_LT(v.errors->h1, kTolerance);
  for (const Eigen::Matrix3d& sigma : v.cell_stress)
    EXPECT_LT((sigma - stress).norm(), kTolerance * stress.norm());
}

// Non-convex faces inside and out, cells not star-shaped about their vertex average (but
// about a point of the L's corner).
TEST(PatchNonConvex, LinearSolutionsOnLShapedPrisms) {
  expect_linear_solutions_on_prisms(test::l_prism_stack(3));
}

// Cells not star-shaped at all: virtual elements, whose projection reproduces linear fields.
TEST(PatchNonConvex, LinearSolutionsOnUShapedPrisms) {
  expect_linear_solutions_on_prisms(test::u_prism_stack(3));
}

TEST(PatchInterface, TwoMaterialsAcrossHangingFaces) {
  const PolyMesh mesh = test::big_cube_next_to_four_small(true);
  expect_interface_reproduced(mesh, {Vec3(1, 0, 0), 1.0, 1.0, 4.0, Vec3(2.0, -3.0, 0.5)});
}

TEST(PatchInterface, TwoMaterialsAcrossCutCells) {
  const Vec3 normal(1.0, 0.6, 0.35);
  const PolyMesh mesh = test::plane_cut_grid(3, normal, 0.93);
  ASSERT_EQ(regions_of(mesh), (std::vector<Index>{1, 2}));
  expect_interface_reproduced(mesh, {normal, 0.93, 1.0, 4.0, Vec3(2.0, -3.0, 0.5)});
}

}  // namespace
}  // namespace volmesh::fem
