// volmesh mesh tet-front end to end: the paper's example with its figures in --json (the
// improver's among them), a valid mesh as re-read with the enclosed volume, the fallback
// forced, and the refusals (exit 1, one line, no output). Same bytes for any thread count: CliMesh.SameBytesForOneAndTwoThreads.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "../support/shell.hpp"
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

TEST(CliTetFront, MeshesThePapersCubeInclusion) {
  const fs::path dir = test::scratch_dir("tet-front-inclusion");
  const fs::path out = dir / "inclusion.vtu";
  const auto r = run_volmesh(
      "mesh tet-front builtin:cube-inclusion --size 2 --json -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["method"], "tet-front");
  EXPECT_EQ(j["tets"], j["cells"]);
  EXPECT_EQ(j["aux_ratio"], 12);
  EXPECT_EQ(j["front"]["aux_deleted"], j["front"]["aux_points"]);  // the domain exhausted
  EXPECT_GT(j["shape"]["min_dihedral_deg"].get<double>(), 0.0);
  for (const char* stage : {"check", "front", "fallback", "improve"})
    EXPECT_TRUE(j["stage_seconds"][stage].is_number()) << stage;
  // The improver's figures: before and after the last pass, the after those of the mesh.
  const auto& improve = j["improve"];
  EXPECT_EQ(improve["after"]["tets"], j["tets"]);
  EXPECT_EQ(improve["after"]["min_dihedral_deg"], j["shape"]["min_dihedral_deg"]);
  EXPECT_EQ(improve["after"]["max_dihedral_deg"], j["shape"]["max_dihedral_deg"]);
  EXPECT_GE(improve["after"]["min_dihedral_deg"].get<double>(),
            improve["before"]["min_dihedral_deg"].get<double>());
  EXPECT_EQ(improve["after"]["tets_below_10_deg"], 0);
  EXPECT_GT(improve["before"]["tets_below_10_deg"], 0);
  EXPECT_GT(improve["operations"]["smoothed"].get<long long>(), 0);
  EXPECT_GT(improve["passes"].get<int>(), 0);
  const PolyMesh mesh = read_mesh(out);
  test::expect_every_cell(mesh, CellShape::Tetrahedron);
  const ValidityReport v = check_validity(mesh);
  EXPECT_TRUE(v.valid());
  ASSERT_EQ(v.region_volume.size(), 2u);
  EXPECT_NEAR(v.region_volume.at(2), 27.0, 27.0 * 1e-12);
  EXPECT_NEAR(v.region_volume.at(1), 512.0 - 27.0, 512.0 * 1e-12);
}

// Stopped at once, the front leaves the whole cube to the fallback, which closes it.
TEST(CliTetFront, AStoppedFrontIsClosedByTheFallback) {
  const fs::path dir = test::scratch_dir("tet-front-stop");
  const fs::path out = dir / "cube.vtu";
  const auto r = run_volmesh(
      "mesh tet-front " + kCube + " --size 0.2 --stop-after 0 --json -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["fallback"]["stalls"], 1);
  EXPECT_EQ(j["fallback"]["cavity_faces"], 12);
  EXPECT_EQ(j["fallback"]["tets"], j["tets"]);
  const ValidityReport v = check_validity(read_mesh(out));
  EXPECT_TRUE(v.valid());
  EXPECT_NEAR(v.total_volume, 0.125, 1e-15);
}

TEST(CliTetFront, BadInputExits1WithOneLineAndNoOutput) {
  const fs::path dir = test::scratch_dir("tet-front-bad");
  const fs::path out = dir / "out.vtu";
  // Two tetrahedra that overlap.
  std::ofstream(dir / "crossing.off")
      << "OFF\n8 8 0\n0 0 0\n2 0 0\n0 2 0\n0 0 2\n0.5 0.5 0.5\n2.5 0.5 0.5\n0.5 2.5 0.5\n"
         "0.5 0.5 2.5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 4 6 5\n3 4 5 7\n3 4 7 6\n3 5 6 7\n";
  // A tetrahedron with a face missing.
  std::ofstream(dir / "open.off")
      << "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n";
  const std::string cube = "mesh tet-front " + kCube + " --size ";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"mesh tet-front " + kCube, "--size"},
      // Not a length: the mesher's refusal, naming the input, not a usage error.
      {cube + "0", "inner_cube.off: --size 0 is not a positive, finite length"},
      {cube + "-1", "inner_cube.off: --size -1 is not a positive, finite length"},
      {cube + "nan", "inner_cube.off: --size nan is not a positive, finite length"},
      {cube + "inf", "inner_cube.off: --size inf is not a positive, finite length"},
      // Beyond the box's diagonal, √3 / 2.
      {cube + "1e9", "inner_cube.off: --size 1e+09 is absurd: longer than the boundary's "
                     "bounding-box diagonal, 0.866, the largest size allowed"},
      {cube + "1e-6", "inner_cube.off: --size 1e-06 is too small: it needs 2.16e+20 auxiliary "
                      "points at --aux-ratio 12, more than the 3.436e+10 that fit in 4 GiB; the "
                      "smallest size allowed is 0.001848"},
      {"mesh tet-front " + (dir / "crossing.off").string() + " --size 0.5", "triangles"},
      {"mesh tet-front " + (dir / "open.off").string() + " --size 0.5", "open.off"},
      // A clean input that remeshing at this size folds: the remeshed surface is named.
      {"mesh tet-front " VOLMESH_CGAL_DATA "/meshes/femur.off --size 0.04 --remesh-surface",
       "the boundary of femur.off remeshed at --size 0.04: triangles"},
  };
  test::expect_refusals(cases, out, dir);
}

}  // namespace
}  // namespace volmesh
