// volmesh mesh tet-front --interior delaunay end to end: the Delaunay core in --json and on
// the progress bar, a valid mesh whose tets are mostly the core's, the same bytes for one and
// two threads on the ball and the torus, and --interior's values checked as usage.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "run_volmesh.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;

TEST(CliTetFrontInterior, TheBallMostlyFromTheCore) {
  const fs::path dir = test::scratch_dir("tet-front-interior-ball");
  const fs::path out = dir / "ball.vtu";
  const auto r = run_volmesh(
      "mesh tet-front builtin:ball --size 0.1 --interior delaunay --json -o " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["interior"]["method"], "delaunay");
  // The core: a ball of radius about 0.84 in tets of the regular tet's volume.
  EXPECT_GT(j["interior"]["core_tets"].get<double>(), 0.5 * j["tets"].get<double>());
  EXPECT_GT(j["interior"]["core_points"].get<long long>(), 0);
  EXPECT_TRUE(j["stage_seconds"]["interior"].is_number());
  const ValidityReport v = check_validity(read_mesh(out));
  EXPECT_TRUE(v.valid()) << (v.problems.empty() ? "" : v.problems.front());
}

TEST(CliTetFrontInterior, SameBytesForOneAndTwoThreads) {
  const fs::path dir = test::scratch_dir("tet-front-interior-threads");
  for (const std::string run :
       {"builtin:ball --size 0.2", VOLMESH_TEST_DATA "/domains/torus.json --size 0.1"}) {
    for (const std::string t : {"1", "2"}) {
      const fs::path out = dir / (t + ".vtu");
      const auto r = run_volmesh("mesh tet-front " + run + " --interior delaunay --threads " + t +
                                     " -o " + out.string(),
                                 dir);
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    EXPECT_EQ(test::slurp(dir / "1.vtu"), test::slurp(dir / "2.vtu")) << run;
    const ValidityReport v = check_validity(read_mesh(dir / "1.vtu"));
    EXPECT_TRUE(v.valid()) << run;
  }
}

TEST(CliTetFrontInterior, TheFrontAloneHasNoCore) {
  const fs::path dir = test::scratch_dir("tet-front-interior-front");
  const auto r = run_volmesh(
      "mesh tet-front builtin:ball --size 0.4 --interior front --json -o " +
          (dir / "ball.vtu").string(),
      dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["interior"]["method"], "front");
  EXPECT_EQ(j["interior"]["core_tets"], 0);
}

TEST(CliTetFrontInterior, OtherValuesAreUsageErrors) {
  const fs::path dir = test::scratch_dir("tet-front-interior-usage");
  const fs::path out = dir / "ball.vtu";
  const auto r = run_volmesh(
      "mesh tet-front builtin:ball --size 0.4 --interior lattice -o " + out.string(), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--interior"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace volmesh
