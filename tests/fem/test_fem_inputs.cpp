// Bad inputs are refused with one clear line naming the region, tag or cell; results are the
// same bytes for any thread count; counts and unused points come out as documented.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <string>

#include "../support/unit_cube_meshes.hpp"
#include "fem_test_meshes.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/topology.hpp"
#include "volmesh/fem/fem.hpp"

namespace volmesh::fem {
namespace {

PoissonProblem dirichlet_everywhere(const PolyMesh& mesh) {
  PoissonProblem p;
  for (Index r : regions_of(mesh)) p.conductivity[r] = 1.0;
  p.source = [](const Vec3& x) { return std::cos(x.x() + 2.0 * x.y()) + x.z(); };
  for (const std::string& tag : mesh.tag_names)
    p.boundary[tag] = {ScalarBoundaryCondition::Kind::dirichlet,
                       [](const Vec3& x) { return x.x() * x.y() - x.z(); }};
  return p;
}

ElasticityProblem clamped(const PolyMesh& mesh) {
  ElasticityProblem p;
  for (Index r : regions_of(mesh)) p.material[r] = {1.0, 0.3};
  p.body_force = [](const Vec3& x) { return Vec3(0.0, -1.0, x.x()); };
  for (const std::string& tag : mesh.tag_names) p.boundary[tag] = {};
  return p;
}

// Runs `solve` and returns the InputError's message (empty if none was thrown).
template <class Solve>
std::string input_error(Solve solve) {
  try {
    solve();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(FemInputs, RegionWithoutConductivityOrMaterial) {
  const PolyMesh mesh = test::big_cube_next_to_four_small(true);
  PoissonProblem poisson = dirichlet_everywhere(mesh);
  poisson.conductivity.erase(2);
  EXPECT_EQ(input_error([&] { solve_poisson(mesh, poisson, Space::polyhedral); }),
            "no conductivity for region 2");
  ElasticityProblem elasticity = clamped(mesh);
  elasticity.material.erase(1);
  EXPECT_EQ(input_error([&] { solve_elasticity(mesh, elasticity, Space::polyhedral); }),
            "no material for region 1");
}

TEST(FemInputs, NonPhysicalCoefficients) {
  const PolyMesh mesh = test::kuhn_cube(1);
  PoissonProblem poisson = dirichlet_everywhere(mesh);
  poisson.conductivity[1] = 0.0;
  EXPECT_NE(input_error([&] {
              solve_poisson(mesh, poisson, Space::p1);
            }).find("conductivity of region 1 is not positive"),
            std::string::npos);
  ElasticityProblem elasticity = clamped(mesh);
  elasticity.material[1].poisson = 0.5;
  EXPECT_NE(input_error([&] {
              solve_elasticity(mesh, elasticity, Space::p1);
            }).find("material of region 1"),
            std::string::npos);
}

TEST(FemInputs, BoundaryTagWithoutCondition) {
  const PolyMesh mesh = test::kuhn_cube(2);
  PoissonProblem poisson = dirichlet_everywhere(mesh);
  poisson.boundary.erase("zmax");
  EXPECT_EQ(input_error([&] { solve_poisson(mesh, poisson, Space::p2); }),
            "no boundary condition for boundary tag 'zmax'");
  ElasticityProblem elasticity = clamped(mesh);
  elasticity.boundary.erase("ymin");
  EXPECT_EQ(input_error([&] { solve_elasticity(mesh, elasticity, Space::p1); }),
            "no boundary condition for boundary tag 'ymin'");
}

TEST(FemInputs, NoDirichletData) {
  const PolyMesh mesh = test::hex_cube(2);
  PoissonProblem poisson = dirichlet_everywhere(mesh);
  for (auto& [tag, condition] : poisson.boundary)
    condition.kind = ScalarBoundaryCondition::Kind::neumann;
  EXPECT_NE(input_error([&] { solve_poisson(mesh, poisson, Space::q1); }).find("no Dirichlet"),
            std::string::npos);
  ElasticityProblem elasticity = clamped(mesh);
  for (auto& [tag, condition] : elasticity.boundary)
    condition.kind = VectorBoundaryCondition::Kind::traction;
  EXPECT_NE(
      input_error([&] { solve_elasticity(mesh, elasticity, Space::q1); }).find("no displacement"),
      std::string::npos);
}

TEST(FemInputs, InvertedAndDegenerateTetrahedra) {
  PolyMesh mesh = test::kuhn_cube(2);
  // Pull the centre vertex across the cube: the first tet (in cell order) that turns
  // inside out is named.
  const Index centre = 13;
  ASSERT_EQ(mesh.points[centre], Vec3(0.5, 0.5, 0.5));
  mesh.points[centre] = Vec3(1.3, 0.5, 0.5);
  const MeshGeometry geometry = mesh_geometry(mesh, build_cell_faces(mesh));
  Index first = kNoIndex;
  for (Index c = 0; c < mesh.num_cells() && first == kNoIndex; ++c)
    if (geometry.cells[c].volume <= 0.0) first = c;
  ASSERT_NE(first, kNoIndex);
  for (Space space : {Space::p1, Space::p2})
    EXPECT_EQ(input_error([&] {
                solve_poisson(mesh, dirichlet_everywhere(mesh), space);
              }).rfind("mesh: cell " + std::to_string(first) + ": inverted tetrahedron", 0),
              0u);

  // Corner 7 of the 5-tet cube, used only by tet 3 = (3, 6, 7, 4), moved onto the plane of
  // 3, 6 and 4: (0,1,0) + ((1,1,1) − (0,1,0))/2 + ((0,0,1) − (0,1,0))/2.
  PolyMesh flat = to_poly_mesh(test::unit_cube_5_tets());
  flat.points[7] = Vec3(0.5, 0.5, 1.0);
  EXPECT_EQ(input_error([&] { solve_poisson(flat, dirichlet_everywhere(flat), Space::p1); }),
            "mesh: cell 3: degenerate tetrahedron (volume 0)");
}

TEST(FemInputs, InvertedHexahedron) {
  PolyMesh mesh = to_poly_mesh(test::unit_cube_hex());
  mesh.points[6] = Vec3(-0.2, -0.2, -0.2);  // the top corner pulled through the opposite one
  const std::string message =
      input_error([&] { solve_poisson(mesh, dirichlet_everywhere(mesh), Space::q1); });
  EXPECT_EQ(message.rfind("mesh: cell 0: inverted hexahedron (scaled Jacobian", 0), 0u) << message;
}

TEST(FemInputs, FoldedPolyhedron) {
  PolyMesh mesh = test::big_cube_next_to_four_small();
  // Small cell 1 spans [1, 1.5]×[0, 0.5]²; fold its outer corner back past the big cube's face.
  Index corner = kNoIndex;
  for (Index p = 0; p < mesh.num_points(); ++p)
    if (mesh.points[p] == Vec3(1.5, 0, 0)) corner = p;
  ASSERT_NE(corner, kNoIndex);
  mesh.points[corner] = Vec3(0.8, 0.0, 0.0);
  const std::string message =
      input_error([&] { solve_elasticity(mesh, clamped(mesh), Space::polyhedral); });
  EXPECT_EQ(message.rfind("mesh: cell 1: inverted, degenerate or folded: volume ", 0), 0u)
      << message;
}

TEST(FemInputs, SpaceThatDoesNotFitTheCells) {
  const PolyMesh hexes = test::hex_cube(2);
  EXPECT_EQ(input_error([&] { solve_poisson(hexes, dirichlet_everywhere(hexes), Space::p1); }),
            "mesh: cell 0 (6 faces) is not a tetrahedron: the p1 space needs a mesh of "
            "tetrahedrons (the polyhedral space takes any cell)");
  const PolyMesh tets = test::kuhn_cube(1);
  EXPECT_NE(input_error([&] {
              solve_elasticity(tets, clamped(tets), Space::q1);
            }).find("is not a hexahedron: the q1 space"),
            std::string::npos);
  const PolyMesh octree = test::big_cube_next_to_four_small();
  EXPECT_NE(input_error([&] {
              solve_poisson(octree, dirichlet_everywhere(octree), Space::p2);
            }).find("cell 0 (9 faces) is not a tetrahedron"),
            std::string::npos);
}

TEST(FemInputs, SpaceNamesRoundTrip) {
  for (Space s : {Space::p1, Space::p2, Space::q1, Space::polyhedral})
    EXPECT_EQ(space_from_name(space_name(s)), s);
  EXPECT_FALSE(space_from_name("p3"));
}

// The same bytes with one thread and with two, through the CG path.
TEST(FemDeterminism, SameBytesForAnyThreadCount) {
  LinearSolverOptions cg;
  cg.kind = LinearSolverOptions::Kind::cg;
  const auto run = [&](int threads, const PolyMesh& mesh, Space space) {
    tbb::task_arena arena(threads);
    ScalarSolution s;
    arena.execute([&] { s = solve_poisson(mesh, dirichlet_everywhere(mesh), space, cg); });
    return s;
  };
  const PolyMesh kuhn = test::kuhn_cube(5);
  PolyMesh octree = test::octree_checkerboard(3);
  test::warp(octree, 0.03);
  for (const auto& [mesh, space] : {std::pair<const PolyMesh&, Space>{kuhn, Space::p2},
                                    std::pair<const PolyMesh&, Space>{octree, Space::polyhedral}}) {
    const ScalarSolution one = run(1, mesh, space), two = run(2, mesh, space);
    ASSERT_EQ(one.point_values.size(), two.point_values.size());
    EXPECT_EQ(std::memcmp(one.point_values.data(), two.point_values.data(),
                          one.point_values.size() * sizeof(double)),
              0);
    EXPECT_EQ(std::memcmp(one.cell_values.data(), two.cell_values.data(),
                          one.cell_values.size() * sizeof(double)),
              0);
    EXPECT_EQ(one.solve.iterations, two.solve.iterations);
    EXPECT_GT(one.solve.iterations, 0);
  }
}

TEST(FemCounts, DofsAndUnusedPoints) {
  PolyMesh mesh = test::kuhn_cube(2);
  const Index vertices = mesh.num_points(),
              edges = static_cast<Index>(build_edges(mesh).edges.size());
  EXPECT_EQ(solve_poisson(mesh, dirichlet_everywhere(mesh), Space::p2).dofs, vertices + edges);
  mesh.points.push_back(Vec3(5, 5, 5));  // used by no cell
  const ScalarSolution s = solve_poisson(mesh, dirichlet_everywhere(mesh), Space::p1);
  EXPECT_EQ(s.dofs, vertices);
  EXPECT_TRUE(std::isnan(s.point_values.back()));
  EXPECT_FALSE(std::isnan(s.point_values.front()));
  EXPECT_EQ(s.solve.method, "ldlt");
}

}  // namespace
}  // namespace volmesh::fem
