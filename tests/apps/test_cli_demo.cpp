// volmesh demo end to end at small levels (the full run is `make demo`): every stage leaves
// its output, and the outputs read back as what the demo reports.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "meshio_fields.hpp"
#include "run_volmesh.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_volmesh;

TEST(CliDemo, SmallRunProducesEveryOutput) {
  const fs::path dir = test::scratch_dir("demo");
  const fs::path out = dir / "demo-output";
  const auto r = run_volmesh("demo -o " + out.string() + " --level 3 --study-levels 2..3", dir);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  for (const char* stage : {"[1/6]", "[2/6]", "[3/6]", "[4/6]", "[5/6]", "[6/6]", "demo done"})
    EXPECT_NE(r.out.find(stage), std::string::npos) << stage << "\n" << r.out;

  // The mesh: valid, all seven regions of builtin:primitives, the same in OpenFOAM form.
  const PolyMesh mesh = read_vtu(out / "primitives.vtu");
  const ValidityReport v = check_validity(mesh);
  EXPECT_TRUE(v.valid());
  EXPECT_EQ(v.region_volume.size(), 7u);
  EXPECT_EQ(read_mesh(out / "primitives.foam").num_cells(), mesh.num_cells());

  // Four pieces that add up to the mesh, each with the solution at its points.
  ASSERT_TRUE(fs::exists(out / "primitives_solution.pvtu"));
  Index cells = 0;
  for (int p = 0; p < 4; ++p) {
    const fs::path piece =
        out / "primitives_solution" / ("primitives_solution_" + std::to_string(p) + ".vtu");
    ASSERT_TRUE(fs::exists(piece)) << piece;
    const auto m = test::meshio_fields(piece);
    ASSERT_TRUE(m.contains("point_data")) << m;
    cells += m["cells"].get<Index>();
    EXPECT_EQ(m["point_data"]["u"]["count"], m["points"]);
    // f = 1, u = 0 on the boundary, k >= 1: 0 < u well below the domain's size squared.
    EXPECT_GT(m["point_data"]["u"]["max_abs"].get<double>(), 1e-4);
    EXPECT_LT(m["point_data"]["u"]["max_abs"].get<double>(), 1.0);
  }
  EXPECT_EQ(cells, mesh.num_cells());

  // The study's outputs.
  const auto summary = nlohmann::json::parse(test::slurp(out / "convergence" / "summary.json"));
  EXPECT_EQ(summary["problem"], "sine");
  EXPECT_EQ(summary["domain"], "builtin:ball");
  EXPECT_EQ(summary["series"][0]["levels"].size(), 2u);
  EXPECT_TRUE(fs::exists(out / "convergence" / "convergence.csv"));
  EXPECT_EQ(test::slurp(out / "convergence" / "convergence.png").substr(1, 3), "PNG");
}

TEST(CliDemo, BadLevelsWriteNothing) {
  const fs::path dir = test::scratch_dir("demo-bad");
  const fs::path out = dir / "demo-output";
  const auto r = run_volmesh("demo -o " + out.string() + " --study-levels 5..3", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace volmesh
