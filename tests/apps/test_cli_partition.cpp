// volmesh partition end to end: PVTU, MSH and VTU outputs read back by meshio and gmsh, the
// statistics in --json, and the refusals (exit 1 with one line, exit 2 for bad usage), never
// leaving a file behind.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <numeric>
#include <set>
#include <sstream>

#include "../partition/partition_test_support.hpp"
#include "../support/unit_cube_meshes.hpp"
#include "run_volmesh.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh::test {
namespace {

namespace fs = std::filesystem;

// The files in a directory, without run_volmesh's stdout.txt and stderr.txt.
std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(entry.path(), dir).string();
    if (name != "stdout.txt" && name != "stderr.txt") names.insert(name);
  }
  return names;
}

// What meshio_pvtu.py prints for each file (empty objects, with a failure, if it fails).
std::vector<nlohmann::json> meshio_sees(const std::vector<fs::path>& files) {
  std::vector<nlohmann::json> seen;
  std::string command = script("meshio_pvtu.py"), output;
  for (const auto& file : files) command += " '" + file.string() + "'";
  if (have_meshio()) {
    EXPECT_EQ(run(command, &output), 0) << output;
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);)
      if (line.starts_with("{")) seen.push_back(nlohmann::json::parse(line));
  }
  seen.resize(files.size(), nlohmann::json::object());
  return seen;
}

class CliPartition : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = scratch_dir(std::string("partition-") + info->name());
    write_vtu(hex_grid(8, 8, 8), dir_ / "mesh.vtu");
  }
  void TearDown() override { fs::remove_all(dir_); }
  RunResult partition(const std::string& args) {
    return run_volmesh("partition " + (dir_ / "mesh.vtu").string() + " " + args, dir_);
  }
  fs::path dir_;
};

TEST_F(CliPartition, PvtuWithStatisticsOpensInMeshio) {
  const auto r = partition("--parts 4 -o " + (dir_ / "out.pvtu").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["parts"], 4);
  EXPECT_EQ(j["method"], "kway");
  EXPECT_EQ(j["cells"], 512);
  const auto cells = j["part_cells"].get<std::vector<int>>();
  EXPECT_EQ(std::accumulate(cells.begin(), cells.end(), 0), 512);
  EXPECT_LE(j["imbalance"].get<double>(), 1.03);
  const auto interface = j["part_interface_faces"].get<std::vector<int>>();
  EXPECT_EQ(std::accumulate(interface.begin(), interface.end(), 0), 2 * j["edge_cut"].get<int>());
  EXPECT_GT(j["edge_cut"].get<int>(), 0);
  EXPECT_TRUE(j["seconds"].contains("metis"));
  EXPECT_EQ(listing(dir_),
            (std::set<std::string>{"mesh.vtu", "out.pvtu", "out", "out/out_0.vtu", "out/out_1.vtu",
                                   "out/out_2.vtu", "out/out_3.vtu"}));

  const auto seen = meshio_sees({dir_ / "out.pvtu", dir_ / "mesh.vtu"});
  const nlohmann::json &parts = seen[0], &whole = seen[1];
  EXPECT_EQ(parts["cells"], whole["cells"]);
  EXPECT_NEAR(parts.value("volume", 0.0), whole.value("volume", -1.0), 1e-12);
  EXPECT_EQ(parts["partitions"], nlohmann::json(cells));
  EXPECT_EQ(parts["cell_ids"], true);
  EXPECT_EQ(parts["point_ids"]["distinct"], 9 * 9 * 9);
  EXPECT_EQ(parts["cell_data"], nlohmann::json({"GlobalCellIds", "partition", "region"}));
  EXPECT_EQ(parts["point_data"], nlohmann::json({"GlobalPointIds"}));
}

// Real cut cells (polyhedra with hanging and cut faces, seven regions), in contiguous parts:
// meshio reads every piece, with each cell's region where the unpartitioned mesh has it and
// the same total volume (meshio fans non-planar faces from a corner, volmesh splits them
// around their centre: up to 1e-5 apart; an average cell is 1.5e-4 of the volume).
TEST_F(CliPartition, CutCellPiecesOpenInMeshio) {
  const fs::path mesh = dir_ / "prim.vtu", out = dir_ / "prim.pvtu";
  ASSERT_EQ(
      run_volmesh("mesh cutcell builtin:primitives --level 4 -o " + mesh.string(), dir_).exit_code,
      0);
  const auto r = run_volmesh(
      "partition " + mesh.string() + " --parts 6 --contiguous -o " + out.string() + " --json",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["all_contiguous"], true);
  EXPECT_LE(j["imbalance"].get<double>(), 1.03);

  const PolyMesh whole = read_vtu(mesh);
  const std::vector<nlohmann::json> both = meshio_sees({out, mesh});
  const nlohmann::json& seen = both[0];
  EXPECT_EQ(seen["files"], 6);
  // The same cells as the unpartitioned mesh, kind by kind, in the pieces and in the whole
  // file: meshio files a polyhedron under its number of distinct vertices.
  nlohmann::json kinds = nlohmann::json::object();
  const CellFaces cell_faces = build_cell_faces(whole);
  for (Index c = 0; c < whole.num_cells(); ++c) {
    std::set<Index> vertices;
    for (Index f : cell_faces.of(c))
      for (Index v : whole.face(f)) vertices.insert(v);
    const std::string kind = "polyhedron" + std::to_string(vertices.size());
    kinds[kind] = kinds.value(kind, 0) + 1;
  }
  EXPECT_EQ(seen["cells"], kinds);
  EXPECT_EQ(both[1]["cells"], kinds);
  EXPECT_EQ(seen["cell_ids"], true);
  EXPECT_EQ(seen["regions"], nlohmann::json(whole.cell_region));
  EXPECT_EQ(seen["point_ids"]["distinct"], whole.num_points());
  EXPECT_EQ(seen["point_ids"]["consistent"], true);
  const double volume = check_validity(whole).total_volume;
  EXPECT_NEAR(seen.value("volume", 0.0), volume, 1e-5 * volume);
}

TEST_F(CliPartition, MshOpensInGmshWithItsPartitions) {
  const auto r = partition("--parts 3 -o " + (dir_ / "out.msh").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("in 3 parts"), std::string::npos) << r.out;
  if (!have_gmsh()) return;
  std::string output;
  EXPECT_EQ(
      run("/usr/bin/gmsh -nopopup '" + (dir_ / "out.msh").string() + "' -check", &output, true), 0)
      << output;
  EXPECT_NE(output.find("3 partitions"), std::string::npos) << output;
  EXPECT_EQ(output.find("Error"), std::string::npos) << output;
}

TEST_F(CliPartition, VtuCarriesThePartitionArray) {
  const auto r = partition("--parts 2 --contiguous -o " + (dir_ / "out.vtu").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["contiguity_enforced"], true);
  EXPECT_EQ(j["all_contiguous"], true);
  EXPECT_EQ(meshio_sees({dir_ / "out.vtu"})[0]["cell_data"],
            nlohmann::json({"partition", "region"}));
}

// One line naming the mesh and the problem; neither the summary nor the piece directory.
TEST_F(CliPartition, MorePartsThanCellsIsOneLineAndNoOutput) {
  const auto r = partition("--parts 513 -o " + (dir_ / "out.pvtu").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("mesh.vtu: cannot split 512 cells into 513 non-empty parts"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(listing(dir_), std::set<std::string>{"mesh.vtu"});
}

TEST_F(CliPartition, PolyhedraToMshIsRefused) {
  write_vtu(big_cube_next_to_four_small(), dir_ / "cubes.vtu");
  const auto r = run_volmesh("partition " + (dir_ / "cubes.vtu").string() + " --parts 2 -o " +
                                 (dir_ / "cubes.msh").string(),
                             dir_);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("cubes.msh: cell 0"), std::string::npos) << r.err;
  EXPECT_EQ(listing(dir_), (std::set<std::string>{"mesh.vtu", "cubes.vtu"}));
}

TEST_F(CliPartition, ForeignPieceDirectoryIsLeftAlone) {
  fs::create_directory(dir_ / "out");
  std::ofstream(dir_ / "out" / "keep.txt") << "mine\n";
  const auto r = partition("--parts 2 -o " + (dir_ / "out.pvtu").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("holds keep.txt"), std::string::npos) << r.err;
  EXPECT_EQ(listing(dir_), (std::set<std::string>{"mesh.vtu", "out", "out/keep.txt"}));
}

TEST_F(CliPartition, BadUsageExitsWith2) {
  for (const std::string args :
       {"--parts 0 -o " + (dir_ / "a.pvtu").string(), "-o " + (dir_ / "a.pvtu").string(),
        "--parts 2 -o " + (dir_ / "a.stl").string(), std::string("--parts 2"),
        "--parts 2 --method metis -o " + (dir_ / "a.pvtu").string()}) {
    const auto r = partition(args);
    EXPECT_EQ(r.exit_code, 2) << args;
  }
  EXPECT_EQ(listing(dir_), std::set<std::string>{"mesh.vtu"});
}

}  // namespace
}  // namespace volmesh::test
