// Cut cells meshed and solved in pieces under mpirun with 1, 2 and 4 ranks: the pieces read
// back by the PVTU reader make up the serial mesh (cells, points, faces, region volumes), the
// solution's errors are the serial ones to the solver tolerance, a fixed rank count gives the
// same bytes, and a failure on one rank while meshing ends every rank. Skipped in a build
// without PETSc or p4est.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "pieces_checks.hpp"
#include "pvtu_compare.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::run_mpi;
using test::run_volmesh;

using CliCutcellPieces = test::MpiTest;

TEST_F(CliCutcellPieces, MeshPiecesMakeTheSerialMesh) {
  const fs::path dir = test::scratch_dir("cutcell-pieces-mesh");
  if (!test::pieces_built(dir)) GTEST_SKIP() << "built without PETSc or p4est";
  // Interfaces of three regions; sharp edges (reflex splits and merges) across the ranks.
  for (const std::string mesh : {"cutcell builtin:primitives --level 4",
                                 "cutcell " VOLMESH_CGAL_DATA "/meshes/fandisk.off --level 5"}) {
    SCOPED_TRACE(mesh);
    const fs::path serial = dir / "serial.vtu";
    ASSERT_EQ(run_volmesh("mesh " + mesh + " -o " + serial.string(), dir).exit_code, 0);
    const PolyMesh reference = read_mesh(serial);
    for (const int ranks : test::kRankCounts) {
      SCOPED_TRACE(ranks);
      const fs::path out = dir / ("p" + std::to_string(ranks) + ".pvtu");
      const auto r = run_mpi(ranks, "mesh " + mesh + " -o " + out.string() + " --json", dir);
      ASSERT_EQ(r.exit_code, 0) << r.err;
      EXPECT_EQ(r.err.find("note:"), std::string::npos) << r.err;  // not the rank-0 path
      const auto j = nlohmann::json::parse(r.out);
      EXPECT_EQ(j["ranks"], ranks);
      EXPECT_EQ(j["cells"], reference.num_cells());
      test::expect_same_mesh(reference, out, ranks);
    }
  }
}

TEST_F(CliCutcellPieces, SolvesOnThePiecesMatchSerial) {
  const fs::path dir = test::scratch_dir("cutcell-pieces-solve");
  if (!test::pieces_built(dir)) GTEST_SKIP() << "built without PETSc or p4est";
  for (const std::string c : {"poisson --problem sine --method cutcell --domain builtin:ball --level 4",
                              "elasticity --problem lame --method cutcell --domain builtin:thick-sphere --level 3"}) {
    SCOPED_TRACE(c);
    const auto s = run_volmesh("solve " + c + " --solver petsc --json -o " + (dir / "serial.vtu").string(), dir);
    ASSERT_EQ(s.exit_code, 0) << s.err;
    const auto expected = nlohmann::json::parse(s.out);
    for (const int ranks : test::kRankCounts) test::expect_solve_on_ranks(c, ranks, expected, dir);
  }
}

TEST_F(CliCutcellPieces, AFixedRankCountGivesTheSameBytes) {
  const fs::path dir = test::scratch_dir("cutcell-pieces-bytes");
  if (!test::pieces_built(dir)) GTEST_SKIP() << "built without PETSc or p4est";
  constexpr int kRanks = 2;
  for (const std::string run : {"mesh cutcell builtin:primitives --level 4 -o ",
                                "solve poisson --problem sine --method cutcell --level 4 -o "})
    test::expect_same_bytes(run, kRanks, dir);
}

TEST_F(CliCutcellPieces, AFailureOnOneRankWhileMeshingEndsEveryRank) {
  const fs::path dir = test::scratch_dir("cutcell-pieces-fail");
  if (!test::pieces_built(dir)) GTEST_SKIP() << "built without PETSc or p4est";
  constexpr int kRanks = 2;
  const fs::path out = dir / "u.pvtu";
  for (const std::string run : {"mesh cutcell builtin:ball --level 4 -o ",
                                "solve poisson --problem sine --method cutcell --level 3 -o "})
    for (const std::string failure : {"mesh@1", "mesh@0"}) {
      SCOPED_TRACE(run + failure);
      const std::string rank = failure.substr(failure.find('@') + 1);
      test::expect_all_failed(test::run_mpi_ranks(kRanks, run + out.string(), dir,
                                                  "VOLMESH_TEST_FAIL_STAGE=" + failure),
                              kRanks, "stage mesh failed on rank " + rank, out);
    }
}

}  // namespace
}  // namespace volmesh
