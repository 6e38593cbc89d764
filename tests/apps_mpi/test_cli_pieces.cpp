// Meshing and solving in pieces under mpirun with 1, 2 and 4 ranks (tests/apps/run_mpi.hpp):
// no rank holds the whole mesh, yet the pieces read back by the PVTU reader make up the
// serial mesh (cells, volume, region volumes), the solution is the serial one to the solver
// tolerance, a fixed rank count gives the same bytes, and a failure on one rank in any stage
// ends every rank. Skipped in a build without PETSc or p4est.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pieces_checks.hpp"
#include "pvtu_compare.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/partitioned_io.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::expect_same_mesh;
using test::kRankCounts;
using test::pieces_built;
using test::run_mpi;
using test::run_volmesh;

using CliPieces = test::MpiTest;

TEST_F(CliPieces, MeshPiecesMakeTheSerialMesh) {
  const fs::path dir = test::scratch_dir("pieces-mesh");
  if (!pieces_built(dir)) GTEST_SKIP() << "built without PETSc or p4est";
  for (const std::string mesh : {"staircase builtin:primitives --level 5 --base-level 3",
                                 "staircase builtin:ball --level 5 --cells-between-levels 2",
                                 "grid builtin:box --level 4"}) {
    SCOPED_TRACE(mesh);
    const fs::path serial = dir / "serial.vtu";
    ASSERT_EQ(run_volmesh("mesh " + mesh + " -o " + serial.string(), dir).exit_code, 0);
    const PolyMesh reference = read_mesh(serial);
    for (const int ranks : kRankCounts) {
      SCOPED_TRACE(ranks);
      const fs::path out = dir / ("p" + std::to_string(ranks) + ".pvtu");
      const auto r = run_mpi(ranks, "mesh " + mesh + " -o " + out.string() + " --json", dir);
      ASSERT_EQ(r.exit_code, 0) << r.err;
      const auto j = nlohmann::json::parse(r.out);  // rank 0 alone prints
      EXPECT_EQ(j["ranks"], ranks);
      EXPECT_EQ(j["cells"], reference.num_cells());
      expect_same_mesh(reference, out, ranks);
    }
  }
}

TEST_F(CliPieces, AFixedRankCountGivesTheSameBytes) {
  const fs::path dir = test::scratch_dir("pieces-bytes");
  if (!pieces_built(dir)) GTEST_SKIP() << "built without PETSc or p4est";
  const std::vector<std::string> runs{
      "mesh staircase builtin:ball --level 5 -o ",
      "solve poisson --problem sine --method staircase --domain builtin:ball --level 4 -o "};
  constexpr int kRanks = 2;
  for (const std::string& run : runs) test::expect_same_bytes(run, kRanks, dir);
}

// The serial solve's figures (PETSc's CG, as under mpirun) against every rank count's, and
// the grid's solutions value by value.
TEST_F(CliPieces, SolvesOnThePiecesMatchSerial) {
  const fs::path dir = test::scratch_dir("pieces-solve");
  if (!pieces_built(dir)) GTEST_SKIP() << "built without PETSc or p4est";
  for (const std::string c :
       {"poisson --problem sine --method staircase --domain builtin:ball --level 4",
        "poisson --problem sine --method staircase --domain builtin:primitives --level 4",
        "poisson --problem sine --method grid --level 4",  // Q1
        "elasticity --problem elastic-patch --method grid --level 3",
        "elasticity --problem lame --method staircase --domain builtin:thick-sphere --level 3"}) {
    SCOPED_TRACE(c);
    const fs::path serial = dir / "serial.vtu";
    const auto s = run_volmesh("solve " + c + " --solver petsc --json -o " + serial.string(), dir);
    ASSERT_EQ(s.exit_code, 0) << s.err;
    const auto expected = nlohmann::json::parse(s.out);
    for (const int ranks : kRankCounts) {
      const fs::path out = test::expect_solve_on_ranks(c, ranks, expected, dir);
      // The grid's pieces keep the serial numbers: point by point through VTK's readers.
      if (c.find("grid") != std::string::npos)
        test::expect_same_solution(test::compare_files(serial, out));
    }
  }
}

TEST_F(CliPieces, AFailureOnOneRankInAnyStageEndsEveryRank) {
  const fs::path dir = test::scratch_dir("pieces-fail");
  if (!pieces_built(dir)) GTEST_SKIP() << "built without PETSc or p4est";
  constexpr int kRanks = 2;
  const fs::path out = dir / "u.pvtu";
  const std::vector<std::pair<std::string, std::vector<std::string>>> runs{
      {"mesh staircase builtin:ball --level 4 -o ", {"mesh@1", "check@1", "write@1", "mesh@0"}},
      {"solve poisson --problem sine --method staircase --level 3 -o ",
       {"mesh@1", "setup@1", "assembly@1", "preconditioner@1", "solve@1", "errors@1", "write@1",
        "assembly@0"}}};
  for (const auto& [run, failures] : runs)
    for (const std::string& failure : failures) {
      SCOPED_TRACE(run + failure);
      const std::string stage = failure.substr(0, failure.find('@'));
      const std::string rank = failure.substr(failure.find('@') + 1);
      test::expect_all_failed(test::run_mpi_ranks(kRanks, run + out.string(), dir,
                                                  "VOLMESH_TEST_FAIL_STAGE=" + failure),
                              kRanks, "stage " + stage + " failed on rank " + rank, out);
    }
}

// What has no pieces takes the rank-0 path, saying so on one line.
TEST_F(CliPieces, MethodsWithoutPiecesAndVtuOutputsTakeTheRankZeroPath) {
  const fs::path dir = test::scratch_dir("pieces-rank-zero");
  if (!pieces_built(dir)) GTEST_SKIP() << "built without PETSc or p4est";
  const fs::path out = dir / "c.pvtu";
  const auto c = run_mpi(2, "solve poisson --problem sine --method hexdc --level 3 --partition octree --json -o " +
                                out.string(), dir);
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_NE(c.err.find("note: hexdc does not mesh in pieces: rank 0 meshes, METIS partitions"),
            std::string::npos)
      << c.err;
  EXPECT_EQ(nlohmann::json::parse(c.out)["partition"], "metis");
  const fs::path vtu = dir / "s.vtu";
  const auto s = run_mpi(2, "mesh staircase builtin:ball --level 3 -o " + vtu.string(), dir);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  EXPECT_NE(s.err.find("rank 0 meshes alone"), std::string::npos) << s.err;
  const fs::path serial = dir / "serial.vtu";
  ASSERT_EQ(run_volmesh("mesh staircase builtin:ball --level 3 -o " + serial.string(), dir).exit_code,
            0);
  EXPECT_EQ(read_mesh(vtu).num_cells(), read_mesh(serial).num_cells());
}

}  // namespace
}  // namespace volmesh
