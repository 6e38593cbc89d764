// The ranks of a distributed solve fail together: a failure on one rank only, in any stage,
// ends every rank with exit 1 by itself (mpirun is told not to stop the others), rank 0
// printing the one error line, and leaves no output; a rank stranded by a failure inside a
// collective stops the run; a solve PETSc stops at its iterations says why. Skipped in a
// build without PETSc.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "run_mpi.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::expect_one_error;
using test::petsc_built;
using test::run_mpi_ranks;

using CliRanksFail = test::MpiTest;

constexpr int kRanks = 2;
// The rank-0 path (METIS); the pieces' path is tests/apps_mpi's.
const std::string kSolve =
    "solve poisson --problem sine --method grid --level 3 --partition metis -o ";

// Every one of the kRanks ranks failed alike (test::expect_all_failed).
void expect_all_failed(const test::RanksResult& r, const std::string& what, const fs::path& out) {
  test::expect_all_failed(r, kRanks, what, out);
}

TEST_F(CliRanksFail, AFailureOnOneRankInAnyStageEndsEveryRank) {
  const fs::path dir = test::scratch_dir("ranks-fail-stages");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  const fs::path out = dir / "u.pvtu";
  // The stages of a distributed solve (fem::stage), in order; rank 0's own failures too.
  const std::vector<std::string> failures{
      "mesh@1",  "partition@1",      "setup@1", "assembly@1", "preconditioner@1",
      "solve@1", "errors@1",         "write@1", "assembly@0", "solve@0"};
  for (const std::string& failure : failures) {
    SCOPED_TRACE(failure);
    const std::string stage = failure.substr(0, failure.find('@'));
    const std::string rank = failure.substr(failure.find('@') + 1);
    expect_all_failed(run_mpi_ranks(kRanks, kSolve + out.string(), dir,
                                    "VOLMESH_TEST_FAIL_STAGE=" + failure),
                      "stage " + stage + " failed on rank " + rank, out);
  }
  // The same stages from a partitioned mesh read one piece per rank.
  const fs::path whole = dir / "mesh.vtu", parts = dir / "parts.pvtu";
  ASSERT_EQ(test::run_volmesh("mesh grid builtin:box --level 3 -o " + whole.string(), dir)
                .exit_code,
            0);
  ASSERT_EQ(test::run_volmesh("partition " + whole.string() + " --parts 2 -o " +
                                  parts.string() + " --quiet",
                              dir)
                .exit_code,
            0);
  expect_all_failed(run_mpi_ranks(kRanks,
                                  "solve poisson --problem sine --mesh " + parts.string() +
                                      " -o " + out.string(),
                                  dir, "VOLMESH_TEST_FAIL_STAGE=mesh@1"),
                    "stage mesh failed on rank 1", out);
}

// Rank 1's piece cannot be written: rank 0's pieces directory (named by its process id,
// which exec keeps) already holds a directory at that piece's name.
TEST_F(CliRanksFail, APieceRankOneCannotWriteEndsEveryRank) {
  const fs::path dir = test::scratch_dir("ranks-fail-piece");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  const fs::path out = dir / "u.pvtu", occupy = dir / "occupy.sh";
  std::ofstream(occupy) << "#!/bin/sh\n"
                           "[ \"$OMPI_COMM_WORLD_RANK\" = 0 ] && mkdir -p \""
                        << dir.string() << "/.u.tmp$$/u_1.vtu/occupied\"\nexec \"$@\"\n";
  fs::permissions(occupy, fs::perms::owner_all);
  expect_all_failed(run_mpi_ranks(kRanks, kSolve + out.string(), dir, "", occupy.string()),
                    "u_1.vtu: cannot write", out);
}

// A failure that leaves the others inside a collective (here rank 1 fails before the PETSc
// matrix that rank 0 goes on to build): rank 1 stops the run after kStrandedSeconds, saying
// why, with its rank.
TEST_F(CliRanksFail, ARankStrandedInACollectiveStopsTheRun) {
  const fs::path dir = test::scratch_dir("ranks-fail-stranded");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  const fs::path out = dir / "u.pvtu";
  const auto r = run_mpi_ranks(kRanks, kSolve + out.string(), dir,
                               "VOLMESH_TEST_FAIL_STAGE=preconditioner@1:start");
  EXPECT_NE(r.run.exit_code, 124) << "the run hung: " << r.run.err;
  // Rank 0, waiting inside PETSc, was stopped; rank 1 stopped the run (MPI_Abort, exit 1,
  // unless mpirun stopped it first).
  EXPECT_EQ(r.rank_exit[0], -1) << r.run.err;
  EXPECT_NE(r.rank_exit[1], 0) << r.run.err;
  test::expect_one_error_line(r.run.err, "stage preconditioner failed on rank 1 (");
  EXPECT_NE(r.run.err.find("rank 1 alone; stopping every rank"), std::string::npos) << r.run.err;
  EXPECT_FALSE(fs::exists(out));
}

// CG stopped by PETSc at its iteration limit: the reason, on one and two ranks.
TEST_F(CliRanksFail, ASolveStoppedAtItsIterationsSaysWhy) {
  const fs::path dir = test::scratch_dir("ranks-fail-iterations");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  const fs::path out = dir / "u.vtu";
  const std::string args =
      kSolve + out.string() + " --solver petsc -ksp_max_it 1 -ksp_error_if_not_converged 1";
  const std::string why = "cg+boomeramg did not converge in 1 iteration (";
  const auto serial = test::run_volmesh(args, dir);
  EXPECT_EQ(serial.exit_code, 1);
  expect_one_error(serial, why);
  EXPECT_NE(serial.err.find("PETSc's reason: DIVERGED_ITS"), std::string::npos) << serial.err;
  const auto two = run_mpi_ranks(kRanks, args, dir);
  expect_all_failed(two, why, out);
  EXPECT_NE(two.run.err.find("PETSc's reason: DIVERGED_ITS"), std::string::npos) << two.run.err;
}

}  // namespace
}  // namespace volmesh
