#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../support/unit_cube_meshes.hpp"
#include "run_volmesh.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;

TEST(Cli, VersionAndUsage) {
  const fs::path dir = test::scratch_dir("usage");
  const auto v = run_volmesh("--version", dir);
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_NE(v.out.find("volmesh"), std::string::npos);
  // Whether the distributed octree is built in: p4est's version, or that it is not.
  EXPECT_TRUE(v.out.find("\ndistributed octree: p4est 2.") != std::string::npos ||
              v.out.find("\ndistributed octree: built without p4est") != std::string::npos)
      << v.out;
  EXPECT_EQ(run_volmesh("", dir).exit_code, 2);
  EXPECT_EQ(run_volmesh("check", dir).exit_code, 2);
  EXPECT_EQ(run_volmesh("info x.off --no-such-flag", dir).exit_code, 2);
  const auto help = run_volmesh("--help", dir);
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("Examples"), std::string::npos);
}

// Every file of the bad-input corpus: exit 1, one line on stderr naming the file, no output.
TEST(Cli, BadSurfacesGiveOneLineAndNoOutput) {
  const fs::path dir = test::scratch_dir("bad");
  int seen = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(VOLMESH_TEST_DATA) / "bad")) {
    const fs::path in = entry.path();
    if (in.filename() == "self_intersecting.off") continue;  // reported, not fatal
    ++seen;
    const fs::path out = dir / "converted.off";
    for (const std::string& cmd : {"info " + in.string(), "convert " + in.string() + " " + out.string()}) {
      const auto r = run_volmesh(cmd, dir);
      EXPECT_EQ(r.exit_code, 1) << cmd;
      EXPECT_EQ(test::count_lines(r.err), 1) << cmd << ": " << r.err;
      EXPECT_NE(r.err.find(in.filename().string()), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(out)) << cmd;
    }
  }
  EXPECT_GE(seen, 7);
}

TEST(Cli, SelfIntersectionIsReportedWithTheTrianglePair) {
  const fs::path dir = test::scratch_dir("selfint");
  const auto r = run_volmesh("info " + (fs::path(VOLMESH_TEST_DATA) / "bad" / "self_intersecting.off").string() + " --json", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_FALSE(j["surface"]["self_intersections"].empty());
  EXPECT_EQ(j["surface"]["self_intersections"][0].size(), 2u);
}

TEST(Cli, ConvertAndCheckAMesh) {
  const fs::path dir = test::scratch_dir("convert");
  write_mesh(to_poly_mesh(kuhn_tet_mesh(Vec3::Zero(), Vec3(2, 1, 1), {4, 2, 2})), dir / "a.vtu");
  const auto c = run_volmesh("convert " + (dir / "a.vtu").string() + " " + (dir / "b.msh").string(), dir);
  ASSERT_EQ(c.exit_code, 0) << c.err;
  const auto r = run_volmesh("check " + (dir / "b.msh").string() + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["validity"]["valid"].get<bool>());
  EXPECT_EQ(j["validity"]["cells"].get<int>(), 6 * 16);
  EXPECT_NEAR(j["validity"]["total_volume"].get<double>(), 2.0, 1e-12);
}

TEST(Cli, InvalidMeshFailsCheckAndIsNotConverted) {
  const fs::path dir = test::scratch_dir("invalid");
  TetMesh t;  // one tet with its vertex order reversed: inside out
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  t.cells = {{0, 2, 1, 3}};
  t.cell_region = {1};
  write_mesh(to_poly_mesh(t), dir / "bad.vtu");
  const auto r = run_volmesh("check " + (dir / "bad.vtu").string(), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.out.find("INVALID"), std::string::npos);
  const auto c = run_volmesh("convert " + (dir / "bad.vtu").string() + " " + (dir / "bad.msh").string(), dir);
  EXPECT_EQ(c.exit_code, 1);
  EXPECT_FALSE(fs::exists(dir / "bad.msh"));
}

// The two-sided Hausdorff distance of a unit cube mesh to the cube [-0.1, 1.1]^3: 0.1 from
// the mesh side, 0.1·sqrt(3) from the surface side (the outer corners).
TEST(Cli, CheckAgainstASurfaceMeasuresVolumeErrorAndHausdorff) {
  const fs::path dir = test::scratch_dir("surface");
  write_mesh(to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {3, 3, 3})), dir / "cube.vtu");
  const HexMesh big = structured_hex_mesh(Vec3::Constant(-0.1), Vec3::Constant(1.1), {1, 1, 1});
  TriSurface s;
  s.points = big.points;
  for (const auto& q : big.boundary_faces) {
    s.triangles.push_back({q[0], q[1], q[2]});
    s.triangles.push_back({q[0], q[2], q[3]});
  }
  write_surface(s, dir / "big.off");
  const auto r = run_volmesh("check " + (dir / "cube.vtu").string() + " --surface " + (dir / "big.off").string() + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out)["surface"];
  EXPECT_NEAR(j["hausdorff_mesh_to_surface"].get<double>(), 0.1, 1e-6);
  EXPECT_NEAR(j["hausdorff_surface_to_mesh"].get<double>(), 0.1 * std::sqrt(3.0), 1e-6);
  EXPECT_NEAR(j["volume_error"].get<double>(), 1.0 / (1.2 * 1.2 * 1.2) - 1.0, 1e-12);
}

TEST(Cli, MissingFileAndUnknownFormat) {
  const fs::path dir = test::scratch_dir("missing");
  const auto r = run_volmesh("check " + (dir / "nope.vtu").string(), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("nope.vtu"), std::string::npos);
  const auto u = run_volmesh("info " + (dir / "thing.xyz").string(), dir);
  EXPECT_EQ(u.exit_code, 1);
  EXPECT_NE(u.err.find("unknown format"), std::string::npos);
}

}  // namespace
}  // namespace volmesh
