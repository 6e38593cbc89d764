// volmesh solve end to end: the VTU holds the solution and its error, which read back in
// meshio and agree with the JSON report; linear exact solutions are reproduced; bad inputs
// give exit 1, one line, and no output file.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "meshio_fields.hpp"
#include "run_volmesh.hpp"
#include "stage_seconds.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;

TEST(CliSolve, PoissonOnTetGridWritesUAndErrorThatReadBack) {
  const fs::path dir = test::scratch_dir("solve-grid");
  const fs::path out = dir / "sine.vtu";
  const auto r = run_volmesh("solve poisson --problem sine --method grid --tets --level 2 -o " +
                                 out.string() + " --json",
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["space"], "p1");  // the default for tets
  EXPECT_EQ(j["cells"], 384);
  EXPECT_EQ(j["dofs"], 125);
  EXPECT_LT(j["residual"].get<double>(), 1e-9);
  const double linf = j["errors"]["linf"];
  EXPECT_GT(linf, 1e-4);  // a real discretisation error ...
  EXPECT_LT(linf, 0.05);  // ... of the size P1 gives at h = 1/4
  EXPECT_LT(j["errors"]["l2"].get<double>(), 0.05);

  EXPECT_EQ(read_vtu(out).num_cells(), 384);
  const auto m = test::meshio_fields(out);
  ASSERT_TRUE(m.contains("point_data")) << m;
  EXPECT_EQ(m["points"], 125);
  EXPECT_EQ(m["point_data"]["u"]["count"], 125);
  EXPECT_GT(m["point_data"]["u"]["max_abs"].get<double>(), 0.5);  // sin products reach ~0.95
  // L∞ is measured at the nodes: the largest |error| written is the reported one.
  EXPECT_NEAR(m["point_data"]["error"]["max_abs"].get<double>(), linf, 1e-12 * linf + 1e-15);
  EXPECT_EQ(m["cell_data"]["region"]["count"], 384);
}

TEST(CliSolve, UserLinearSolutionIsReproducedOnHexesAndFromAMeshFile) {
  const fs::path dir = test::scratch_dir("solve-user");
  // Hex grid: the default space is Q1, which contains the linear field.
  const fs::path hex = dir / "hex.vtu";
  const auto a = run_volmesh("solve poisson --exact '1+2*x-y+3*z' --method grid --level 2 -o " +
                                 hex.string() + " --json",
                             dir);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const auto ja = nlohmann::json::parse(a.out);
  EXPECT_EQ(ja["space"], "q1");
  EXPECT_LT(ja["errors"]["linf"].get<double>(), 1e-10);

  // A mesh read from a file is its own domain: its boundary carries the data.
  const fs::path mesh = dir / "tets.vtu";
  write_vtu(to_poly_mesh(kuhn_tet_mesh(Vec3::Zero(), Vec3(2, 1, 1), {4, 2, 2})), mesh);
  const fs::path out = dir / "patch.vtu";
  const auto b = run_volmesh("solve poisson --problem patch-linear --mesh " + mesh.string() +
                                 " -o " + out.string() + " --json",
                             dir);
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const auto jb = nlohmann::json::parse(b.out);
  EXPECT_EQ(jb["space"], "p1");
  EXPECT_LT(jb["errors"]["linf"].get<double>(), 1e-10);
  EXPECT_LT(test::meshio_fields(out)["point_data"]["error"]["max_abs"].get<double>(), 1e-10);
}

// builtin:primitives at level 4: cut cells at junctions of three surfaces, one with no star
// centre (a virtual element), and boundary points on sharp edges, where the mesh's own
// boundary is the true one. A linear field is reproduced to the solver's tolerance.
TEST(CliSolve, LinearSolutionIsReproducedOnMultiMaterialCutCells) {
  const fs::path dir = test::scratch_dir("solve-primitives");
  const fs::path mesh = dir / "primitives.vtu", out = dir / "u.vtu";
  const auto m = run_volmesh(
      "mesh cutcell builtin:primitives --level 4 -o " + mesh.string(), dir);
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const auto r = run_volmesh("solve poisson --exact '1+2*x-y+3*z' --mesh " + mesh.string() +
                                 " -o " + out.string() + " --json",
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["space"], "polyhedral");
  EXPECT_LT(j["errors"]["linf"].get<double>(), 1e-7);
  EXPECT_LT(j["errors"]["h1"].get<double>(), 1e-7);
}

TEST(CliSolve, ElasticityWritesDisplacementErrorAndVonMises) {
  const fs::path dir = test::scratch_dir("solve-elastic");
  const fs::path out = dir / "patch.vtu";
  const auto r = run_volmesh("solve elasticity --problem elastic-patch --method grid --level 2 "
                             "-o " + out.string() + " --json",
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["space"], "q1");
  EXPECT_EQ(j["dofs"], 3 * 125);
  EXPECT_LT(j["errors"]["linf"].get<double>(), 1e-10);
  const auto m = test::meshio_fields(out);
  ASSERT_TRUE(m.contains("point_data")) << m;
  EXPECT_EQ(m["point_data"]["displacement"]["components"], 3);
  EXPECT_GT(m["point_data"]["displacement"]["max_abs"].get<double>(), 0.1);
  EXPECT_LT(m["point_data"]["error"]["max_abs"].get<double>(), 1e-10);
  EXPECT_EQ(m["cell_data"]["von_mises"]["count"], 64);
  // A linear displacement has a constant, non-zero stress.
  EXPECT_GT(m["cell_data"]["von_mises"]["max_abs"].get<double>(), 0.1);
}

// The fast end of validation/fem/lame.sh (which asserts the L2 slope >= 1.8 over levels
// 4..7): the thick-walled sphere under internal pressure on cut cells, levels 4 and 5. The
// inner sphere spans only 3.6 and 7.3 cells of its radius there, so the L2 rate is still
// pre-asymptotic (1.64 to 1.74 measured; 2.0 from level 5 to 6 and 6 to 7): this pins the
// rate and the error size the long study starts from.
TEST(CliSolve, LameOnCutCellsApproachesSecondOrder) {
  const fs::path dir = test::scratch_dir("solve-lame");
  std::vector<nlohmann::json> runs;
  for (int level : {4, 5}) {
    const auto r = run_volmesh(
        "solve elasticity --problem lame --method cutcell --domain builtin:thick-sphere "
        "--level " + std::to_string(level) + " -o " + (dir / "lame.vtu").string() + " --json",
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    runs.push_back(nlohmann::json::parse(r.out));
  }
  const auto rate = [&](const char* norm) {
    return std::log(runs[0]["errors"][norm].get<double>() / runs[1]["errors"][norm].get<double>()) /
           std::log(runs[0]["h"].get<double>() / runs[1]["h"].get<double>());
  };
  EXPECT_GE(rate("l2"), 1.5);
  EXPECT_GE(rate("h1"), 0.85);
  EXPECT_LT(runs[1]["errors"]["l2"].get<double>(), 2.5e-3);
  EXPECT_LT(runs[1]["residual"].get<double>(), 1e-9);
}

// Exit 1, one line naming the problem, no output file.
void expect_refused(const std::string& args, const std::string& what, const fs::path& dir,
                    const fs::path& out) {
  const auto r = run_volmesh(args + " -o " + out.string(), dir);
  EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << args << "\n" << r.err;
  EXPECT_FALSE(fs::exists(out)) << args;
}

// Every stage of a solve has its time in --json, and they add up to the total: meshed by a
// method (no check), read from a file (checked), finite volumes, elasticity.
TEST(CliSolve, StageSecondsAddUpToTheTotal) {
  const fs::path dir = test::scratch_dir("solve-seconds");
  const std::vector<std::string> stages{"mesh",     "check",          "partition",
                                        "setup",    "assembly",       "preconditioner",
                                        "solve",    "errors",         "write"};
  const fs::path mesh = dir / "ball.vtu";
  ASSERT_EQ(run_volmesh("mesh cutcell builtin:ball --level 3 -o " + mesh.string(), dir).exit_code,
            0);
  for (const std::string& args :
       {std::string("solve poisson --problem sine --method cutcell --domain builtin:ball --level 4"),
        "solve poisson --problem sine --mesh " + mesh.string(),
        "solve poisson --problem sine --mesh " + mesh.string() + " --space fv",
        std::string("solve elasticity --problem elastic-patch --method grid --level 3")}) {
    const auto r = run_volmesh(args + " -o " + (dir / "u.vtu").string() + " --json", dir);
    ASSERT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    const auto seconds = nlohmann::json::parse(r.out)["seconds"];
    SCOPED_TRACE(args);
    test::expect_stages_add_up(seconds, stages);
    // Only a mesh read from a file is checked.
    EXPECT_EQ(seconds["check"].get<double>() > 0.0, args.find("--mesh") != std::string::npos);
  }
}

TEST(CliSolve, BadInputsGiveOneLineAndNoOutput) {
  const fs::path dir = test::scratch_dir("solve-bad");
  const fs::path out = dir / "out.vtu";
  expect_refused("solve poisson --problem no-such --method grid --level 1", "no-such", dir, out);
  expect_refused("solve poisson --problem lame --method grid --level 1", "elasticity", dir, out);
  expect_refused("solve elasticity --problem sine --method grid --level 1", "Poisson", dir, out);
  expect_refused("solve poisson --problem sine --method grid --domain builtin:ball --level 1",
                 "builtin:ball", dir, out);
  expect_refused("solve poisson --problem sine --method grid --level 1 --space p1", "p1", dir, out);
  expect_refused("solve poisson --exact 'sin(x' --method grid --level 1", "--exact", dir, out);

  // Region 2 has no conductivity: builtin:box has region 1 only.
  HexMesh hex = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2});
  hex.cell_region.assign(hex.cell_region.size(), 2);
  const fs::path region2 = dir / "region2.vtu";
  write_vtu(to_poly_mesh(hex), region2);
  expect_refused("solve poisson --problem sine --domain builtin:box --mesh " + region2.string(),
                 "region2.vtu: no conductivity for region 2", dir, out);
  expect_refused(
      "solve elasticity --problem elastic-patch --domain builtin:box --mesh " + region2.string(),
      "region2.vtu: no material for region 2", dir, out);

  // Mirrored points turn every cell inside out.
  PolyMesh inverted = to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2}));
  for (Vec3& p : inverted.points) p.x() = -p.x();
  const fs::path inside_out = dir / "inverted.vtu";
  write_vtu(inverted, inside_out);
  expect_refused("solve poisson --problem sine --mesh " + inside_out.string(),
                 "inverted.vtu: invalid mesh", dir, out);
}

TEST(CliSolve, UsageErrors) {
  const fs::path dir = test::scratch_dir("solve-usage");
  const std::string out = (dir / "out.vtu").string();
  for (const std::string& args : std::vector<std::string>{
           "solve poisson --problem sine --method grid --level 1",             // no -o
           "solve heat --problem sine --method grid --level 1 -o " + out,     // unknown kind
           "solve poisson --problem sine -o " + out,                          // no mesh
           "solve poisson --problem sine --method grid -o " + out,            // no level
           "solve poisson --problem sine --method grid --level 1 -o x.msh",   // not a VTU
           "solve poisson --problem sine --exact x --method grid --level 1 -o " + out}) {
    const auto r = run_volmesh(args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
}

}  // namespace
}  // namespace volmesh
