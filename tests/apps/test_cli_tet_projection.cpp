// volmesh mesh tet-projection end to end: exact figures in --json, the mesh as re-read, two
// regions from nested surfaces, P1 on the tets, and the refusals (exit 1, one line, no
// output). Same bytes for any thread count: CliMesh.SameBytesForOneAndTwoThreads.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "../support/shell.hpp"
#include "cell_shapes.hpp"
#include "refusals.hpp"
#include "run_volmesh.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;

// The cube [0.25, 0.75]^3 (tests/data/domains/inner_cube.off): volume 1/8.
const std::string kCube = VOLMESH_TEST_DATA "/domains/inner_cube.off";

TEST(CliTetProjection, MeshesACubeExactlyAndReportsItsFigures) {
  const fs::path dir = test::scratch_dir("tet-projection-cube");
  const fs::path out = dir / "cube.vtu";
  const auto r = run_volmesh("mesh tet-projection " + kCube + " --json -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["method"], "tet-projection");
  EXPECT_EQ(j["surface_triangles"], 12);
  EXPECT_EQ(j["top"].get<Index>() + j["bot"].get<Index>() + j["wall"].get<Index>(), 12);
  EXPECT_EQ(j["enclosed_volume"]["exact"], "1/8");
  EXPECT_EQ(j["rounding"]["repaired_prisms"], 0);
  EXPECT_EQ(j["rounding"]["directions_tried"], 1);
  EXPECT_EQ(j["steiner_points"]["interior"], j["prisms"]);
  EXPECT_EQ(j["tets"], j["cells"]);
  for (const char* stage : {"check", "classify", "project", "prisms", "stitch", "fill", "round"})
    EXPECT_TRUE(j["stage_seconds"][stage].is_number()) << stage;
  const PolyMesh mesh = read_mesh(out);
  test::expect_every_cell(mesh, CellShape::Tetrahedron);
  const ValidityReport v = check_validity(mesh);
  EXPECT_TRUE(v.valid());
  EXPECT_DOUBLE_EQ(v.total_volume, 0.125);
}

// --improve: the mesh coarsened and improved is valid, fills the same volume and has no
// more tets than the plain one, its worst dihedral angle no smaller.
TEST(CliTetProjection, ImproveCoarsensAndKeepsTheVolume) {
  const fs::path dir = test::scratch_dir("tet-projection-improve");
  const fs::path plain = dir / "plain.vtu", improved = dir / "improved.vtu";
  const auto p = run_volmesh("mesh tet-projection builtin:schoenhardt --json -o " + plain.string(), dir);
  ASSERT_EQ(p.exit_code, 0) << p.err;
  const auto r = run_volmesh(
      "mesh tet-projection builtin:schoenhardt --improve --json -o " + improved.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& c = j["improvement"]["coarsen"];
  EXPECT_LE(c["tets"][1].get<Index>(), c["tets"][0].get<Index>());
  const auto& improved_by = j["improvement"]["improve"];
  EXPECT_GE(improved_by["after"]["min_dihedral_deg"].get<double>(),
            improved_by["before"]["min_dihedral_deg"].get<double>());
  const ValidityReport before = check_validity(read_mesh(plain));
  const ValidityReport after = check_validity(read_mesh(improved));
  EXPECT_TRUE(after.valid());
  EXPECT_LE(read_mesh(improved).num_cells(), read_mesh(plain).num_cells());
  EXPECT_NEAR(after.total_volume, before.total_volume, 1e-12 * before.total_volume);
}

// nested.json: the unit cube around inner_cube.off, labels 1 and 2; the inner surface is an
// interface, so the mesh's boundary is the outer cube's alone.
TEST(CliTetProjection, NestedSurfacesGiveTheirRegions) {
  const fs::path dir = test::scratch_dir("tet-projection-nested");
  const fs::path out = dir / "nested.vtu";
  const auto r = run_volmesh(
      "mesh tet-projection " VOLMESH_TEST_DATA "/domains/nested.json -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ValidityReport v = check_validity(read_mesh(out));
  EXPECT_TRUE(v.valid());
  ASSERT_EQ(v.region_volume.size(), 2u);
  EXPECT_NEAR(v.region_volume.at(2), 0.125, 1e-15);
  EXPECT_NEAR(v.region_volume.at(1), 0.875, 1e-15);
}

// A hexagonal prism twisted by 60 degrees has its top corners over its bottom ones up to the
// rounding of sin and cos: along the axes, some faces come out with no area in doubles, so
// the mesh is made again along a tilted direction.
TEST(CliTetProjection, TriesOtherDirectionsWhenRoundingFails) {
  const fs::path dir = test::scratch_dir("tet-projection-tilt");
  const fs::path out = dir / "twisted.vtu";
  const auto r = run_volmesh(
      "mesh tet-projection builtin:twisted-prism:6:60 --json -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["rounding"]["directions_tried"].get<int>(), 1);
  EXPECT_NE(j["direction"].get<std::string>().find("tilted"), std::string::npos);
  EXPECT_TRUE(check_validity(read_mesh(out)).valid());
  const auto fixed = run_volmesh(
      "mesh tet-projection builtin:twisted-prism:6:60 --axis z -o " + (dir / "z.vtu").string(),
      dir);
  EXPECT_EQ(fixed.exit_code, 1);  // with the axis given, no other is tried
  EXPECT_EQ(test::count_lines(fixed.err), 1) << fixed.err;
  EXPECT_FALSE(fs::exists(dir / "z.vtu"));
}

// P1 on the projection's tets: the centres of the prisms are the only interior nodes.
TEST(CliTetProjection, SolvesPoissonInP1) {
  const fs::path dir = test::scratch_dir("tet-projection-solve");
  const auto r = run_volmesh("solve poisson --problem sine --method tet-projection --domain " +
                                 kCube + " --json -o " + (dir / "u.vtu").string(),
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["space"], "p1");
  EXPECT_TRUE(j["iterations"].is_number());
  EXPECT_LT(j["errors"]["l2"].get<double>(), 0.1);
}

TEST(CliTetProjection, BadInputExits1WithOneLineAndNoOutput) {
  const fs::path dir = test::scratch_dir("tet-projection-bad");
  const fs::path out = dir / "out.vtu";
  // Two tetrahedra that overlap.
  std::ofstream(dir / "crossing.off")
      << "OFF\n8 8 0\n0 0 0\n2 0 0\n0 2 0\n0 0 2\n0.5 0.5 0.5\n2.5 0.5 0.5\n0.5 2.5 0.5\n"
         "0.5 0.5 2.5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 4 6 5\n3 4 5 7\n3 4 7 6\n3 5 6 7\n";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"mesh tet-projection builtin:ball", "not given by triangulated surfaces"},
      {"mesh tet-projection " + kCube + " --level 3", "no --level"},
      {"mesh tet-projection " + (dir / "crossing.off").string(), "intersect"},
  };
  test::expect_refusals(cases, out, dir);
  const auto usage = run_volmesh("mesh tet-projection " + kCube + " --axis w -o " + out.string(), dir);
  EXPECT_EQ(usage.exit_code, 2);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace volmesh
