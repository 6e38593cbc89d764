// `volmesh check --surface` against an analytic domain: the distance to the TRUE surfaces.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>

#include "../support/unit_cube_meshes.hpp"
#include "run_volmesh.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;

// A unit cube mesh against builtin:box (the unit cube): no distance, no volume error; the
// samples a sixth of the mean cell edge apart.
TEST(CliCheckReference, AMeshOfTheBoxIsOnItsTrueSurface) {
  const fs::path dir = test::scratch_dir("check_box");
  write_mesh(to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {4, 4, 4})), dir / "cube.vtu");
  const auto r = run_volmesh("check " + (dir / "cube.vtu").string() + " --surface builtin:box --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out)["surface"];
  EXPECT_LT(j["hausdorff"].get<double>(), 1e-15);
  EXPECT_NEAR(j["volume_error"].get<double>(), 0.0, 1e-14);
  EXPECT_NEAR(j["sample_spacing"].get<double>(), 0.25 / 6.0, 1e-15);
}

// The same cube against a taller box written as a domain file: 0.1 off along the top, the
// volume known in closed form.
TEST(CliCheckReference, ADomainFileOfOneSolid) {
  const fs::path dir = test::scratch_dir("check_json");
  write_mesh(to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2})), dir / "cube.vtu");
  std::ofstream(dir / "taller.json")
      << R"({"solids": [{"label": 1, "solid": {"type": "box", "min": [0, 0, 0], "max": [1, 1, 1.1]}}]})";
  const auto r = run_volmesh("check " + (dir / "cube.vtu").string() + " --surface " +
                                 (dir / "taller.json").string() + " --json",
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out)["surface"];
  EXPECT_NEAR(j["hausdorff_mesh_to_surface"].get<double>(), 0.1, 1e-12);
  EXPECT_NEAR(j["hausdorff_surface_to_mesh"].get<double>(), 0.1, 1e-12);
  EXPECT_NEAR(j["volume_error"].get<double>(), 1.0 / 1.1 - 1.0, 1e-12);
}

// A domain of triangulated surfaces is no analytic reference (its surfaces are files that
// --surface takes one by one): one line, exit 1.
TEST(CliCheckReference, ANonAnalyticDomainIsRefused) {
  const fs::path dir = test::scratch_dir("check_layers");
  write_mesh(to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {1, 1, 1})), dir / "cube.vtu");
  const std::string nested = VOLMESH_TEST_DATA "/domains/nested.json";
  const auto r = run_volmesh("check " + (dir / "cube.vtu").string() + " --surface " + nested + " --json", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(nested + ": not analytic"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace volmesh
