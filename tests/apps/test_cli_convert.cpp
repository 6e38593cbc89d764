// volmesh convert --decompose tets end to end: a cut-cell mesh of builtin:primitives reaches
// MSH, MEDIT and Abaqus as conforming tetrahedra that gmsh and meshio read with the
// polyhedral mesh's volume in every region; without the option the element formats refuse
// polyhedra and name it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../fem/fem_test_meshes.hpp"
#include "../support/shell.hpp"
#include "../support/unit_cube_meshes.hpp"
#include "run_volmesh.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::count_lines;
using test::run_volmesh;

// The octree depth of the cut-cell mesh: cut cells of every kind, seven regions, seconds.
constexpr int kLevel = 3;
// Relative agreement of volumes: the pieces fill the cells as volmesh measures them, up to
// rounding, and meshio's sums of tets and of fanned faces agree with that.
constexpr double kRelativeVolume = 1e-12;

// What meshio_region_volumes.py prints for each file; empty objects, with a failure, if it
// fails.
std::vector<nlohmann::json> meshio_region_volumes(const std::vector<fs::path>& files) {
  std::string command = "/usr/bin/python3 '" + std::string(VOLMESH_TEST_SOURCE) +
                        "/io/external/meshio_region_volumes.py'";
  for (const fs::path& file : files) command += " '" + file.string() + "'";
  std::string output;
  EXPECT_EQ(test::run(command, &output, true), 0)
      << output << "(`make test` installs python3-meshio)";
  return test::json_lines(output, files.size());
}

void expect_same_volumes(const ValidityReport& expected, const nlohmann::json& seen,
                         const std::string& what) {
  const double tolerance = kRelativeVolume * expected.total_volume;
  EXPECT_NEAR(seen.value("volume", 0.0), expected.total_volume, tolerance) << what;
  const nlohmann::json regions = seen.value("regions", nlohmann::json::object());
  EXPECT_EQ(regions.size(), expected.region_volume.size()) << what;
  for (const auto& [region, volume] : expected.region_volume)
    EXPECT_NEAR(regions.value(std::to_string(region), 0.0), volume, tolerance)
        << what << ": region " << region;
}

TEST(CliConvert, CutCellsReachEveryFormatAsConformingTets) {
  const fs::path dir = test::scratch_dir("convert-decompose");
  const fs::path vtu = dir / "prim.vtu";
  const auto m = run_volmesh("mesh cutcell builtin:primitives --level " + std::to_string(kLevel) +
                                 " -o " + vtu.string(),
                             dir);
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const PolyMesh polyhedral = read_vtu(vtu);
  const ValidityReport expected = check_validity(polyhedral);
  ASSERT_TRUE(expected.valid());
  ASSERT_GE(expected.region_volume.size(), 7u);

  std::vector<fs::path> files{vtu};
  for (const char* ext : {".msh", ".mesh", ".inp"}) {
    const fs::path out = dir / (std::string("prim") + ext);
    const auto r =
        run_volmesh("convert " + vtu.string() + " " + out.string() + " --decompose tets", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("decomposed " + std::to_string(polyhedral.num_cells()) + " cells into "),
              std::string::npos)
        << r.err;
    files.push_back(out);
  }

  // volmesh reads its MSH back: valid tetrahedra, the same volume in every region.
  const PolyMesh tets = read_mesh(dir / "prim.msh");
  const ValidityReport back = check_validity(tets);
  EXPECT_TRUE(back.valid()) << (back.problems.empty() ? "" : back.problems.front());
  EXPECT_NEAR(back.total_volume, expected.total_volume, kRelativeVolume * expected.total_volume);
  for (const auto& [region, volume] : expected.region_volume)
    EXPECT_NEAR(back.region_volume.at(region), volume, kRelativeVolume * expected.total_volume);

  // gmsh parses the MSH and finds it coherent (no duplicate nodes or elements).
  std::string output;
  ASSERT_TRUE(fs::exists("/usr/bin/gmsh")) << "`make test` installs gmsh";
  EXPECT_EQ(test::run("/usr/bin/gmsh -nopopup '" + (dir / "prim.msh").string() + "' -check",
                      &output, true),
            0)
      << output;
  EXPECT_EQ(output.find("Error"), std::string::npos) << output;
  EXPECT_EQ(output.find("Warning"), std::string::npos) << output;
  EXPECT_NE(output.find("Checking mesh coherence"), std::string::npos) << output;

  // meshio reads the polyhedra with their regions and the tetrahedra of the three formats,
  // all positive, with the same volumes.
  const auto seen = meshio_region_volumes(files);
  Index polyhedra = 0;
  const nlohmann::json vtu_cells = seen[0].value("cells", nlohmann::json::object());
  for (const auto& [kind, count] : vtu_cells.items())
    polyhedra += kind.starts_with("polyhedron") ? count.get<Index>() : 0;
  EXPECT_EQ(polyhedra, polyhedral.num_cells());
  expect_same_volumes(expected, seen[0], "prim.vtu");
  for (std::size_t i = 1; i < files.size(); ++i) {
    const std::string what = files[i].filename().string();
    EXPECT_EQ(seen[i].value("cells", nlohmann::json::object()),
              nlohmann::json({{"tetra", tets.num_cells()}}))
        << what;
    EXPECT_GT(seen[i].value("min_tet", 0.0), 0.0) << what;
    expect_same_volumes(expected, seen[i], what);
  }
}

// The hexdc mesher's hexes go to every element format as they are: meshio reads hexahedra
// with positive volumes summing to the mesh's, gmsh finds the MSH coherent.
TEST(CliConvert, HexdcHexesReachEveryFormat) {
  const fs::path dir = test::scratch_dir("convert-hexdc");
  const fs::path vtu = dir / "ball.vtu";
  const auto m = run_volmesh("mesh hexdc builtin:ball --level 3 -o " + vtu.string(), dir);
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const PolyMesh hexes = read_vtu(vtu);
  const ValidityReport expected = check_validity(hexes);
  ASSERT_TRUE(expected.valid());

  std::vector<fs::path> files{vtu};
  for (const char* ext : {".msh", ".mesh", ".inp"}) {
    const fs::path out = dir / (std::string("ball") + ext);
    const auto r = run_volmesh("convert " + vtu.string() + " " + out.string(), dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    files.push_back(out);
  }
  std::string output;
  ASSERT_TRUE(fs::exists("/usr/bin/gmsh")) << "`make test` installs gmsh";
  EXPECT_EQ(test::run("/usr/bin/gmsh -nopopup '" + (dir / "ball.msh").string() + "' -check",
                      &output, true),
            0)
      << output;
  EXPECT_EQ(output.find("Error"), std::string::npos) << output;
  EXPECT_EQ(output.find("Warning"), std::string::npos) << output;

  const auto seen = meshio_region_volumes(files);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string what = files[i].filename().string();
    EXPECT_EQ(seen[i].value("cells", nlohmann::json::object()),
              nlohmann::json({{"hexahedron", hexes.num_cells()}}))
        << what;
    EXPECT_GT(seen[i].value("min_hex", 0.0), 0.0) << what;
    expect_same_volumes(expected, seen[i], what);
  }
}

// The projection mesher's tets written straight to each format: meshio reads the same
// tets and volume from every file, gmsh checks the MSH (at a tolerance below the closest
// pair of its points: Steiner points where projected edges cross nearly parallel can lie
// 1e-8 apart, which gmsh's default tolerance would call duplicates).
TEST(CliConvert, TetProjectionTetsReachEveryFormat) {
  const fs::path dir = test::scratch_dir("convert-tet-projection");
  const std::string surface = VOLMESH_CGAL_DATA "/meshes/anchor.off";
  std::vector<fs::path> files;
  for (const char* ext : {".vtu", ".msh", ".mesh", ".inp"}) {
    files.push_back(dir / (std::string("anchor") + ext));
    const auto r = run_volmesh("mesh tet-projection " + surface + " -o " + files.back().string(),
                               dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const PolyMesh tets = read_vtu(files.front());
  const ValidityReport expected = check_validity(tets);
  ASSERT_TRUE(expected.valid());
  std::string output;
  ASSERT_TRUE(fs::exists("/usr/bin/gmsh")) << "`make test` installs gmsh";
  EXPECT_EQ(test::run("/usr/bin/gmsh -nopopup '" + files[1].string() + "' -tol 1e-15 -check",
                      &output, true),
            0)
      << output;
  EXPECT_EQ(output.find("Error"), std::string::npos) << output;
  const auto seen = meshio_region_volumes(files);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const std::string what = files[i].filename().string();
    EXPECT_EQ(seen[i].value("cells", nlohmann::json::object()),
              nlohmann::json({{"tetra", tets.num_cells()}}))
        << what;
    expect_same_volumes(expected, seen[i], what);
  }
}

// Without --decompose the element formats refuse a polyhedron, name the option and write
// nothing; a cell that no point sees whole is named; the option takes "tets" only.
TEST(CliConvert, PolyhedraNeedTheOptionAndStarShapedCells) {
  const fs::path dir = test::scratch_dir("convert-polyhedra");
  write_vtu(test::big_cube_next_to_four_small(true), dir / "cubes.vtu");
  for (const char* ext : {".msh", ".mesh", ".inp"}) {
    const fs::path out = dir / (std::string("cubes") + ext);
    const auto r = run_volmesh("convert " + (dir / "cubes.vtu").string() + " " + out.string(), dir);
    EXPECT_EQ(r.exit_code, 1) << ext;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(out.string() + ": cell 0 is a polyhedron with 9 faces"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("--decompose tets"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << ext;
  }

  write_vtu(test::u_prism_stack(1), dir / "u.vtu");
  const auto u = run_volmesh(
      "convert " + (dir / "u.vtu").string() + " " + (dir / "u.msh").string() + " --decompose tets",
      dir);
  EXPECT_EQ(u.exit_code, 1);
  EXPECT_EQ(count_lines(u.err), 1) << u.err;
  EXPECT_NE(u.err.find((dir / "u.vtu").string() +
                       ": cell 0 (region 1, 10 faces): no point inside sees all its faces"),
            std::string::npos)
      << u.err;
  EXPECT_FALSE(fs::exists(dir / "u.msh"));

  EXPECT_EQ(run_volmesh("convert " + (dir / "cubes.vtu").string() + " " +
                            (dir / "cubes.msh").string() + " --decompose hexes",
                        dir)
                .exit_code,
            2);
}

// `volmesh mesh --decompose tets` writes the cut cells straight to an element format: valid
// tetrahedra with the polyhedral mesh's region volumes (the summary stays the mesher's own).
TEST(CliMeshDecompose, CutCellsGoStraightToAnElementFormat) {
  const fs::path dir = test::scratch_dir("mesh-decompose");
  const fs::path msh = dir / "prim.msh";
  const auto r = run_volmesh("mesh cutcell builtin:primitives --level " + std::to_string(kLevel) +
                                 " -o " + msh.string() + " --decompose tets --json",
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json summary = nlohmann::json::parse(r.out);
  const PolyMesh tets = read_mesh(msh);
  const ValidityReport back = check_validity(tets);
  EXPECT_TRUE(back.valid()) << (back.problems.empty() ? "" : back.problems.front());
  EXPECT_EQ(summary["decomposed"]["tetrahedra"].get<Index>(), tets.num_cells());
  EXPECT_GT(tets.num_cells(), summary["cells"].get<Index>());
  const double total = summary["validity"]["total_volume"].get<double>();
  EXPECT_NEAR(back.total_volume, total, kRelativeVolume * total);
  for (const auto& [region, entry] : summary["regions"].items())
    EXPECT_NEAR(back.region_volume.at(std::stoi(region)), entry["volume"].get<double>(),
                kRelativeVolume * total)
        << "region " << region;

  const fs::path inp = dir / "prim.inp";
  const auto refused =
      run_volmesh("mesh cutcell builtin:primitives --level 2 -o " + inp.string(), dir);
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("--decompose tets"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(inp));
}

}  // namespace
}  // namespace volmesh
