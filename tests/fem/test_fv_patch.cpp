// Cell-centred finite volumes, exactness: a linear solution is reproduced on orthogonal grids
// without correction and, once the non-orthogonal correction has converged, on warped hexes,
// octree cells with hanging faces and plane-cut cells (the same meshes give O(1) errors
// without it); a layered solution with a kink on a material interface is reproduced across
// axis-aligned and oblique interfaces (harmonic k); bad data are InputErrors; the result does
// not depend on the thread count.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <functional>
#include <string>

#include "fem_test_meshes.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/fem/finite_volume.hpp"
#include "volmesh/fem/problems.hpp"

namespace volmesh::fem {
namespace {

PolyMesh warped(PolyMesh mesh, double amplitude) {
  test::warp(mesh, amplitude);
  return mesh;
}

// patch-linear of the problem library, k = 2.5 in every region of the mesh.
PoissonProblem patch_problem(const PolyMesh& mesh) {
  const auto box = make_builtin_domain("box");
  PoissonProblem p = make_poisson_problem("patch-linear", *box, mesh.tag_names);
  p.to_true_boundary = nullptr;  // the meshes' boundaries are the cube's sides
  for (Index r : regions_of(mesh)) p.conductivity[r] = 2.5;
  return p;
}

struct PatchCase {
  std::string name;
  std::function<PolyMesh()> mesh;
};
std::ostream& operator<<(std::ostream& os, const PatchCase& c) { return os << c.name; }

class FvPatch : public ::testing::TestWithParam<PatchCase> {};

TEST_P(FvPatch, LinearSolutionIsExactWithCorrectionAndNotWithout) {
  const PolyMesh mesh = GetParam().mesh();
  ASSERT_TRUE(check_validity(mesh).valid());
  const PoissonProblem problem = patch_problem(mesh);
  FvReport report;
  const ScalarSolution s = solve_poisson_fv(mesh, problem, {}, {}, &report);
  ASSERT_TRUE(s.errors);
  EXPECT_TRUE(report.converged);
  EXPECT_GT(report.corrections, 0);
  EXPECT_LT(s.errors->linf, 1e-10);
  EXPECT_LT(s.errors->h1, 1e-10);  // least squares reproduce the linear field's gradient
  EXPECT_LT(s.solve.residual, 1e-10);
  EXPECT_EQ(static_cast<Index>(s.cell_values.size()), mesh.num_cells());
  EXPECT_TRUE(s.point_values.empty());

  FvOptions plain;
  plain.non_orthogonal_correction = false;
  const ScalarSolution uncorrected = solve_poisson_fv(mesh, problem, {}, plain);
  EXPECT_GT(uncorrected.errors->linf, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(
    Meshes, FvPatch,
    ::testing::Values(
        PatchCase{"WarpedHexes", [] { return warped(test::hex_cube(5), 0.05); }},
        PatchCase{"OctreeCheckerboard", [] { return test::octree_checkerboard(3); }},
        PatchCase{"PlaneCutCells",
                  [] { return test::plane_cut_grid(4, Vec3(1.0, 0.6, 0.35), 0.93); }},
        PatchCase{"WarpedPlaneCutCells",
                  [] {
                    return warped(test::plane_cut_grid(4, Vec3(1.0, 0.6, 0.35), 0.93), 0.04);
                  }}),
    [](const auto& info) { return info.param.name; });

TEST(FvPatchOrthogonal, LinearSolutionIsExactWithoutCorrectionSolves) {
  const PolyMesh mesh = test::hex_cube(4);
  FvReport report;
  const ScalarSolution s = solve_poisson_fv(mesh, patch_problem(mesh), {}, {}, &report);
  EXPECT_EQ(report.corrections, 0);
  EXPECT_LT(s.errors->linf, 1e-13);
  EXPECT_LT(s.errors->h1, 1e-12);
}

TEST(FvPatchNeumann, FluxesOnFiveSidesOfAWarpedGrid) {
  const PolyMesh mesh = warped(test::hex_cube(5), 0.05);
  PoissonProblem p = patch_problem(mesh);
  const Vec3 gradient = p.exact_gradient(Vec3::Zero());
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const std::string tag = std::string(1, char('x' + axis)) + (side ? "max" : "min");
      if (tag == "xmin") continue;
      const double flux = 2.5 * gradient[axis] * (side ? 1.0 : -1.0);
      p.boundary[tag] = {ScalarBoundaryCondition::Kind::neumann,
                         [flux](const Vec3&) { return flux; }};
    }
  FvReport report;
  const ScalarSolution s = solve_poisson_fv(mesh, p, {}, {}, &report);
  EXPECT_TRUE(report.converged);
  EXPECT_LT(s.errors->linf, 1e-10);
  EXPECT_LT(s.errors->h1, 1e-10);
}

// u = a s below the interface s = n·x = s0 and continues with slope a k1/k2 above it.
PoissonProblem layered_problem(const PolyMesh& mesh, const Vec3& normal, double offset) {
  const Vec3 n = normal.normalized();
  const double s0 = offset / normal.norm(), k1 = 1.0, k2 = 10.0, a = 1.0, b = a * k1 / k2;
  const ScalarFunction u = [=](const Vec3& x) {
    const double s = n.dot(x);
    return s < s0 ? 0.5 + a * s : 0.5 + a * s0 + b * (s - s0);
  };
  PoissonProblem p;
  p.conductivity = {{1, k1}, {2, k2}};
  for (const std::string& tag : mesh.tag_names)
    p.boundary[tag] = {ScalarBoundaryCondition::Kind::dirichlet, u};
  p.exact = u;
  p.exact_gradient = [=](const Vec3& x) -> Vec3 { return (n.dot(x) < s0 ? a : b) * n; };
  return p;
}

TEST(FvInterface, HarmonicConductivityReproducesALayeredSolution) {
  PolyMesh grid = test::hex_cube(8);
  const MeshGeometry geometry = mesh_geometry(grid, build_cell_faces(grid));
  for (Index c = 0; c < grid.num_cells(); ++c)
    grid.cell_region[c] = geometry.cells[c].centre.x() < 0.5 ? 1 : 2;
  const ScalarSolution aligned =
      solve_poisson_fv(grid, layered_problem(grid, Vec3::UnitX(), 0.5), {});
  EXPECT_LT(aligned.errors->linf, 1e-13);
  EXPECT_LT(aligned.errors->h1, 1e-12);

  // An oblique interface through cut cells: exact once the correction has converged.
  const Vec3 normal(1.0, 0.6, 0.35);
  const PolyMesh cut = test::plane_cut_grid(6, normal, 0.93);
  FvReport report;
  const ScalarSolution oblique =
      solve_poisson_fv(cut, layered_problem(cut, normal, 0.93), {}, {}, &report);
  EXPECT_TRUE(report.converged);
  EXPECT_LT(oblique.errors->linf, 1e-10);
  EXPECT_LT(oblique.errors->h1, 1e-10);
}

std::string error_of(const PolyMesh& mesh, const PoissonProblem& p) {
  try {
    solve_poisson_fv(mesh, p, {});
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(FvInputs, MissingDataAreInputErrors) {
  const PolyMesh cut = test::plane_cut_grid(3, Vec3(1.0, 0.6, 0.35), 0.93);  // regions 1, 2
  PoissonProblem p = patch_problem(cut);
  p.conductivity.erase(2);
  EXPECT_NE(error_of(cut, p).find("region 2"), std::string::npos) << error_of(cut, p);
  p.conductivity[2] = 0.0;
  EXPECT_NE(error_of(cut, p).find("positive"), std::string::npos) << error_of(cut, p);

  p = patch_problem(cut);
  p.boundary.erase("ymax");
  EXPECT_NE(error_of(cut, p).find("boundary tag ymax"), std::string::npos) << error_of(cut, p);

  p = patch_problem(cut);
  for (auto& [tag, bc] : p.boundary) bc.kind = ScalarBoundaryCondition::Kind::neumann;
  EXPECT_NE(error_of(cut, p).find("Dirichlet"), std::string::npos) << error_of(cut, p);
}

TEST(FvDeterminism, SameBytesForOneAndTwoThreads) {
  const PolyMesh mesh = warped(test::octree_checkerboard(3), 0.03);
  const auto box = make_builtin_domain("box");
  const PoissonProblem p = make_poisson_problem("sine", *box, mesh.tag_names);
  const auto run = [&](int threads) {
    tbb::task_arena arena(threads);
    ScalarSolution s;
    arena.execute([&] { s = solve_poisson_fv(mesh, p, {}); });
    return s;
  };
  const ScalarSolution one = run(1), two = run(2);
  EXPECT_EQ(one.cell_values, two.cell_values);
  EXPECT_EQ(one.errors->l2, two.errors->l2);
}

}  // namespace
}  // namespace volmesh::fem
