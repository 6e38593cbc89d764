// The tet meshers' boundaries end to end: analytic domains triangulated at h first (the
// ball's mesh fills the inscribed polyhedron, the thick sphere's cavity is left out),
// --remesh-surface with its Hausdorff distance, a solve and a convergence study of tet-front
// on the ball (second order in L2 for P1).
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "cell_shapes.hpp"
#include "refusals.hpp"
#include "run_volmesh.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;

// The cube [0.25, 0.75]^3 (tests/data/domains/inner_cube.off): volume 1/8.
const std::string kCube = VOLMESH_TEST_DATA "/domains/inner_cube.off";

// Every boundary point of the mesh on the sphere |x| = r for one of the radii, or at most
// `chord` inside it (a point on a flat triangle between the sphere's points).
void expect_boundary_on_spheres(const PolyMesh& mesh, std::initializer_list<double> radii,
                                double chord = 0.0) {
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!mesh.is_boundary(f)) continue;
    for (const Index v : mesh.face(f)) {
      bool near = false;
      for (const double r : radii) {
        const double off = mesh.points[v].norm() - r;
        near = near || (off < 1e-9 && off > -chord - 1e-9);
      }
      ASSERT_TRUE(near) << "boundary vertex " << v << " at |x| = " << mesh.points[v].norm();
    }
  }
}

TEST(CliTetBoundary, TheBallIsTriangulatedAtHThenFilled) {
  const fs::path dir = test::scratch_dir("tet-boundary-ball");
  const double exact = 4.0 / 3.0 * std::numbers::pi;
  double previous = 1.0;
  for (const double h : {0.4, 0.2}) {
    const fs::path out = dir / "ball.vtu";
    const auto r = run_volmesh("mesh tet-front builtin:ball --size " + std::to_string(h) +
                                   " --json -o " + out.string(),
                               dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j["boundary"]["triangulated"].get<bool>());
    EXPECT_EQ(j["boundary"]["surfaces"], 1);
    EXPECT_TRUE(j["stage_seconds"]["surface"].is_number());
    const PolyMesh mesh = read_mesh(out);
    test::expect_every_cell(mesh, CellShape::Tetrahedron);
    const ValidityReport v = check_validity(mesh);
    EXPECT_TRUE(v.valid());
    expect_boundary_on_spheres(mesh, {1.0});
    // The inscribed polyhedron: below 4π/3 by less than 4π h²/8, less so as h shrinks.
    const double error = exact - v.total_volume;
    EXPECT_GT(error, 0.0) << h;
    EXPECT_LT(error, 4.0 * std::numbers::pi * h * h / 8.0) << h;
    EXPECT_LT(error, previous) << h;
    previous = error;
  }
}

// The hollow ball: meshed between the two spheres only, both of them boundary.
TEST(CliTetBoundary, TheThickSphereLeavesItsCavityOut) {
  const fs::path dir = test::scratch_dir("tet-boundary-shell");
  const fs::path out = dir / "shell.vtu";
  const auto r = run_volmesh("mesh tet-front builtin:thick-sphere --size 0.25 --json -o " +
                                 out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["boundary"]["surfaces"], 2);
  const PolyMesh mesh = read_mesh(out);
  const ValidityReport v = check_validity(mesh);
  EXPECT_TRUE(v.valid());
  ASSERT_EQ(v.region_volume.size(), 1u);
  const double exact = 4.0 / 3.0 * std::numbers::pi * (1.0 - 0.125);
  EXPECT_NEAR(v.total_volume, exact, 0.05 * exact);
  expect_boundary_on_spheres(mesh, {0.5, 1.0});
}

TEST(CliTetBoundary, TetProjectionTriangulatesAtTheSurfaceSize) {
  const fs::path dir = test::scratch_dir("tet-boundary-projection");
  const fs::path out = dir / "ball.vtu";
  const auto r = run_volmesh(
      "mesh tet-projection builtin:ball --surface-size 0.3 -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const PolyMesh mesh = read_mesh(out);
  EXPECT_TRUE(check_validity(mesh).valid());
  // The projection mesher puts Steiner points on the surface triangles: within their
  // sagitta, below (2 · 0.3)² / 8 for edges up to twice the size.
  expect_boundary_on_spheres(mesh, {1.0}, 0.6 * 0.6 / 8.0);
}

// The cube remeshed to 0.1: more triangles, its edges kept (the volume exact), the Hausdorff
// distance reported both ways and within the measuring error.
TEST(CliTetBoundary, RemeshSurfaceReportsTheHausdorffDistance) {
  const fs::path dir = test::scratch_dir("tet-boundary-remesh");
  const fs::path out = dir / "cube.vtu";
  const auto r = run_volmesh(
      "mesh tet-front " + kCube + " --size 0.1 --remesh-surface --json -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& remeshed = j["boundary"]["remeshed"];
  EXPECT_EQ(remeshed["input_triangles"], 12);
  EXPECT_EQ(remeshed["sharp_edges"], 12);
  EXPECT_GT(j["boundary"]["triangles"].get<int>(), 100);
  // Within the measuring error (1e-3 h) of zero: the faces stay in their planes.
  EXPECT_LE(remeshed["hausdorff"]["to_input"].get<double>(), 2e-4);
  EXPECT_LE(remeshed["hausdorff"]["from_input"].get<double>(), 2e-4);
  const ValidityReport v = check_validity(read_mesh(out));
  EXPECT_TRUE(v.valid());
  EXPECT_NEAR(v.total_volume, 0.125, 1e-12);
}

TEST(CliTetBoundary, SolveMeshesTheLevelsOctreeCellEdge) {
  const fs::path dir = test::scratch_dir("tet-boundary-solve");
  const auto r = run_volmesh("solve poisson --problem sine --method tet-front --domain "
                             "builtin:ball --level 2 --json -o " + (dir / "u.vtu").string(),
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // The ball's octree root: its side 2 (1 + 2 · 0.05), over 2^2.
  EXPECT_NEAR(j["h"].get<double>(), 2.2 / 4.0, 1e-12);
}

// P1 on tet-front meshes of the ball, the boundary data on the true sphere: second order in L2.
// Disabled until the fallback closes every stalled cavity: at level 4 (h = 0.1375) the
// front stalls on a 116-face cavity that no projection direction closes.
// The slope of a convergence study of the sine problem on tet-front meshes of the ball, the
// boundary data on the true sphere. Levels 3 and 4 are h = 0.275 and 0.1375.
nlohmann::json ball_series(const std::string& space, const std::string& levels) {
  const fs::path dir = test::scratch_dir("tet-boundary-study-" + space);
  const auto r = run_volmesh("study convergence --problem sine --method tet-front --domain "
                             "builtin:ball --space " + space + " --levels " + levels +
                                 " --json -o " + (dir / "out").string(),
                             dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["series"][0]["space"], space);
  return j["series"][0]["slope"];
}

TEST(CliTetBoundary, P1IsSecondOrderOnTheBall) {
  const auto slope = ball_series("p1", "3..4");
  EXPECT_GE(slope["L2"].get<double>(), 1.8);
  EXPECT_GE(slope["H1"].get<double>(), 0.9);
}

// Boundary edge nodes on the true sphere: third order in L2 where straight P2 stops near 2.5.
TEST(CliTetBoundary, IsoparametricP2IsThirdOrderOnTheBall) {
  const auto slope = ball_series("p2", "2..4");
  EXPECT_GE(slope["L2"].get<double>(), 2.7);
  EXPECT_GE(slope["H1"].get<double>(), 1.8);
}

TEST(CliTetBoundary, BadInputExits1WithOneLineAndNoOutput) {
  const fs::path dir = test::scratch_dir("tet-boundary-bad");
  const fs::path out = dir / "out.vtu";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"mesh tet-projection builtin:ball", "not given by triangulated surfaces"},
      {"mesh tet-front builtin:ball --size 1e-7", "too small"},
  };
  test::expect_refusals(cases, out, dir);
}

}  // namespace
}  // namespace volmesh
