// volmesh mesh tet-front's graded sizes end to end: --json's size_field (uniform where the
// boundary fits --size, growing to --interior-size inside), a valid mesh with the enclosed
// volume, and the refusals of absurd interior sizes (exit 1, one line, no output).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../support/shell.hpp"
#include "refusals.hpp"
#include "run_volmesh.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;

// The cube [0.25, 0.75]^3 (tests/data/domains/inner_cube.off): volume 1/8, diagonal √3 / 2.
const std::string kCube = VOLMESH_TEST_DATA "/domains/inner_cube.off";

TEST(CliTetGrading, JsonGivesTheSizeFieldAndTheMeshIsValid) {
  const fs::path dir = test::scratch_dir("tet-grading");
  const fs::path out = dir / "cube.vtu";
  const auto uniform = run_volmesh("mesh tet-front " + kCube + " --size 0.3 --json -o " +
                                       out.string(), dir);
  ASSERT_EQ(uniform.exit_code, 0) << uniform.err;
  const auto u = nlohmann::json::parse(uniform.out)["size_field"];
  EXPECT_EQ(u["min"], 0.3);
  EXPECT_EQ(u["max"], 0.3);
  EXPECT_EQ(u["grading_rate"], 0.0);

  const auto graded = run_volmesh("mesh tet-front " + kCube +
                                      " --size 0.3 --interior-size 0.5 --json -o " + out.string(),
                                  dir);
  ASSERT_EQ(graded.exit_code, 0) << graded.err;
  const auto g = nlohmann::json::parse(graded.out)["size_field"];
  EXPECT_EQ(g["min"], 0.3);
  EXPECT_EQ(g["max"], 0.5);
  EXPECT_EQ(g["grading_rate"], 0.25);
  const ValidityReport v = check_validity(read_mesh(out));
  EXPECT_TRUE(v.valid());
  EXPECT_NEAR(v.total_volume, 0.125, 0.125 * 1e-12);
}

TEST(CliTetGrading, AbsurdInteriorSizesExit1WithOneLineAndNoOutput) {
  const fs::path dir = test::scratch_dir("tet-grading-bad");
  const fs::path out = dir / "out.vtu";
  const std::string cube = "mesh tet-front " + kCube + " --size 0.3 --interior-size ";
  const std::vector<std::pair<std::string, std::string>> cases{
      {cube + "0", "inner_cube.off: --interior-size 0 is not a positive, finite length"},
      {cube + "-1", "inner_cube.off: --interior-size -1 is not a positive, finite length"},
      {cube + "nan", "inner_cube.off: --interior-size nan is not a positive, finite length"},
      {cube + "inf", "inner_cube.off: --interior-size inf is not a positive, finite length"},
      {cube + "big", "inner_cube.off: --interior-size big is not a number"},
      {cube + "0.1", "inner_cube.off: --interior-size 0.1 is smaller than --size 0.3"},
      {cube + "1e9", "inner_cube.off: --interior-size 1e+09 is absurd: longer than the "
                     "boundary's bounding-box diagonal, 0.866, the largest size allowed"},
  };
  test::expect_refusals(cases, out, dir);
}

}  // namespace
}  // namespace volmesh
