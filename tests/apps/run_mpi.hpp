#pragma once
// volmesh under mpirun, and what the distributed tests share: whether the build has PETSc,
// and the one error line a failed run prints.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "run_volmesh.hpp"

namespace volmesh::test {

// `volmesh --version` names the PETSc version ("PETSc 3.18.5") in a build that has it, and
// says "built without PETSc" otherwise.
inline bool petsc_built(const std::filesystem::path& dir) {
  const std::string version = run_volmesh("--version", dir).out;
  const std::size_t at = version.find("PETSc ");
  return at != std::string::npos && at + 6 < version.size() &&
         std::isdigit(static_cast<unsigned char>(version[at + 6]));
}

inline void allow_mpirun_as_root() {
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
}

// `volmesh args` under mpirun with `ranks` processes (root allowed, more ranks than cores).
inline RunResult run_mpi(int ranks, const std::string& args, const std::filesystem::path& dir) {
  allow_mpirun_as_root();
  return run_captured("mpirun --oversubscribe -np " + std::to_string(ranks) + " " +
                          std::string(VOLMESH_BINARY) + " " + args,
                      dir);
}

// A hang fails the test this many seconds into it, well before ctest's limit.
inline constexpr int kHangSeconds = 120;

// A run whose ranks each end by themselves: mpirun does not stop the others when one exits
// non-zero (and then exits 0 itself), and every rank's exit code is kept (rank_exit[r]; -1: it
// never ended), the whole run stopped after kHangSeconds (exit code 124). `environment` ("NAME=value ...") is given to
// every rank, `wrapper` (a command line) runs before volmesh on each and must exec it.
struct RanksResult {
  RunResult run;
  std::vector<int> rank_exit;
};
inline RanksResult run_mpi_ranks(int ranks, const std::string& args,
                                 const std::filesystem::path& dir,
                                 const std::string& environment = "",
                                 const std::string& wrapper = "") {
  allow_mpirun_as_root();
  const std::filesystem::path codes = dir / "rank-exit";
  std::filesystem::remove_all(codes);
  std::filesystem::create_directories(codes);
  // Each rank's shell runs volmesh and writes its exit code to rank-exit/<rank>.
  const std::string rank_shell = "sh -c '" + environment + " " + wrapper +
                                 " \"$0\" \"$@\"; echo $? >" + codes.string() +
                                 "/$OMPI_COMM_WORLD_RANK' ";
  RanksResult r;
  r.run = run_captured("timeout -k 5 " + std::to_string(kHangSeconds) +
                           " mpirun --mca orte_abort_on_non_zero_status 0 --oversubscribe -np " +
                           std::to_string(ranks) + " " + rank_shell + VOLMESH_BINARY + " " + args,
                       dir);
  for (int rank = 0; rank < ranks; ++rank) {
    const std::string code = slurp(codes / std::to_string(rank));
    r.rank_exit.push_back(code.empty() ? -1 : std::atoi(code.c_str()));
  }
  return r;
}

// In the sanitizer build, LeakSanitizer would report what Open MPI and PETSc keep past their
// finalize calls (in components they unload, whose frames only the slow unwinder sees): those
// libraries' leaks are suppressed for the processes these tests start. Release builds ignore it.
class MpiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    setenv("LSAN_OPTIONS",
           "suppressions=" VOLMESH_TEST_SOURCE "/apps/external/lsan_mpi.supp:fast_unwind_on_malloc=0",
           1);
  }
};

// One "volmesh: error:" line on stderr (rank 0's), saying `what`.
inline void expect_one_error_line(const std::string& err, const std::string& what) {
  std::size_t lines = 0, at = 0;
  while ((at = err.find("volmesh: error:", at)) != std::string::npos) ++lines, ++at;
  EXPECT_EQ(lines, 1u) << err;
  EXPECT_NE(err.find(what), std::string::npos) << err;
}

// One line on stderr from rank 0, a non-zero exit, and no hang.
inline void expect_one_error(const RunResult& r, const std::string& what) {
  EXPECT_NE(r.exit_code, 0);
  expect_one_error_line(r.err, what);
}

// Every one of `ranks` ranks ended by itself with exit 1, rank 0 printed `what` on one line,
// and neither the output nor its pieces' directory exists.
inline void expect_all_failed(const RanksResult& r, int ranks, const std::string& what,
                              const std::filesystem::path& out) {
  EXPECT_NE(r.run.exit_code, 124) << "the run hung: " << r.run.err;
  EXPECT_EQ(r.rank_exit, std::vector<int>(ranks, 1)) << r.run.err;
  expect_one_error_line(r.run.err, what);
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(out.parent_path() / out.stem()));
}

}  // namespace volmesh::test
