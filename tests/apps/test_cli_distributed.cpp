// The PETSc backend and the distributed solve end to end: PETSc's CG + BoomerAMG agrees with
// Eigen's solver to the solver tolerance, its iteration count stays flat under refinement,
// `mpirun -np 1|2 volmesh solve` gives the serial solution (the 2-rank PVTU read by VTK's
// parallel reader has the serial VTU's cells and values), a study's convergence slope is the
// same on 2 ranks, a mesh partitioned once and read one piece per rank gives the same
// solution, and bad set-ups give one error line and a non-zero exit. Skipped in a
// build without PETSc.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pvtu_compare.hpp"
#include "run_mpi.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;
using test::expect_one_error;
using test::petsc_built;
using test::run_mpi;
using test::run_volmesh;

// CG + BoomerAMG's iteration counts over refinement stay within this fraction of their mean.
constexpr double kFlatIterations = 0.2;

using test::compare_files;
using test::expect_same_solution;

using CliDistributed = test::MpiTest;

const std::vector<std::string> kCases{
    "poisson --problem sine --method grid --tets --level 3",                   // P1
    "poisson --problem sine --method grid --level 4",                          // Q1
    "poisson --problem sine --method cutcell --domain builtin:ball --level 4",  // polyhedral
    "elasticity --problem lame --method cutcell --domain builtin:thick-sphere --level 3",
    "elasticity --problem elastic-patch --method grid --level 3"};             // Q1, 3 per node

TEST_F(CliDistributed, PetscMatchesEigenAndOneAndTwoRanksMatchSerial) {
  const fs::path dir = test::scratch_dir("distributed-match");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  for (const std::string& c : kCases) {
    SCOPED_TRACE(c);
    // The serial PETSc solve writes one piece, compared through the parallel reader too.
    const fs::path eigen = dir / "eigen.vtu", petsc = dir / "petsc.pvtu";
    const auto e = run_volmesh("solve " + c + " --solver eigen --json -o " + eigen.string(), dir);
    ASSERT_EQ(e.exit_code, 0) << e.err;
    const auto p = run_volmesh("solve " + c + " --solver petsc --json -o " + petsc.string(), dir);
    ASSERT_EQ(p.exit_code, 0) << p.err;
    EXPECT_EQ(nlohmann::json::parse(p.out)["linear_solver"], "cg+boomeramg");
    EXPECT_EQ(nlohmann::json::parse(e.out)["unknowns"], nlohmann::json::parse(p.out)["unknowns"]);
    expect_same_solution(compare_files(eigen, petsc));
    // The rank-0 path: its pieces keep the serial point numbers (the cut cells' pieces, whose
    // numbers differ, are compared in tests/apps_mpi).
    for (int ranks : {1, 2}) {
      const fs::path out = dir / ("ranks" + std::to_string(ranks) + ".pvtu");
      const auto r = run_mpi(ranks, "solve " + c + " --partition metis --json -o " + out.string(), dir);
      ASSERT_EQ(r.exit_code, 0) << r.err;
      const auto j = nlohmann::json::parse(r.out);  // rank 0 alone prints
      EXPECT_EQ(j["ranks"], ranks);
      EXPECT_EQ(j["unknowns"], nlohmann::json::parse(e.out)["unknowns"]);
      expect_same_solution(compare_files(eigen, out));
    }
  }
}

// A mesh partitioned once by `volmesh partition` and read by the ranks, one piece each: the
// solution is the serial Eigen solve's and the broadcast path's, Poisson and elasticity.
TEST_F(CliDistributed, RanksReadAPartitionedMeshAndMatchSerial) {
  const fs::path dir = test::scratch_dir("distributed-pieces");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"mesh cutcell builtin:ball --level 3", "poisson --problem sine"},             // polyhedral
      {"mesh grid builtin:box --level 3", "elasticity --problem elastic-patch"}};  // Q1
  for (const auto& [mesh, problem] : cases) {
    SCOPED_TRACE(mesh);
    const fs::path whole = dir / "mesh.vtu", eigen = dir / "eigen.vtu";
    ASSERT_EQ(run_volmesh(mesh + " -o " + whole.string(), dir).exit_code, 0);
    const std::string solve = "solve " + problem + " --json --mesh ";
    const auto e = run_volmesh(solve + whole.string() + " --solver eigen -o " + eigen.string(), dir);
    ASSERT_EQ(e.exit_code, 0) << e.err;
    const auto unknowns = nlohmann::json::parse(e.out)["unknowns"];
    for (int ranks : {1, 2}) {
      const std::string n = std::to_string(ranks);
      const fs::path parts = dir / ("parts" + n + ".pvtu"), out = dir / ("read" + n + ".pvtu"),
                     sent = dir / ("sent" + n + ".pvtu");
      const auto p = run_volmesh("partition " + whole.string() + " --parts " + n + " -o " +
                                     parts.string() + " --quiet",
                                 dir);
      ASSERT_EQ(p.exit_code, 0) << p.err;
      const auto read = run_mpi(ranks, solve + parts.string() + " -o " + out.string(), dir);
      ASSERT_EQ(read.exit_code, 0) << read.err;
      const auto j = nlohmann::json::parse(read.out);
      EXPECT_EQ(j["ranks"], ranks);
      EXPECT_EQ(j["unknowns"], unknowns);
      expect_same_solution(compare_files(eigen, out));
      // The broadcast path on the same mesh.
      const auto b = run_mpi(ranks, solve + whole.string() + " -o " + sent.string(), dir);
      ASSERT_EQ(b.exit_code, 0) << b.err;
      expect_same_solution(compare_files(eigen, sent));
    }
    // One process reads the whole set.
    const fs::path one = dir / "one.vtu";
    const auto s = run_volmesh(solve + (dir / "parts2.pvtu").string() + " --solver eigen -o " +
                                   one.string(),
                               dir);
    ASSERT_EQ(s.exit_code, 0) << s.err;
    EXPECT_EQ(nlohmann::json::parse(s.out)["errors"], nlohmann::json::parse(e.out)["errors"]);
  }
}

// PETSc's own options reach the solver over the defaults: the rigid-body interpolation for
// elasticity (whose set-up does not return with the default Chebyshev smoothing in hypre 2.26)
// and GAMG, each to the Eigen solve's solution.
TEST_F(CliDistributed, ElasticityOptionsOverTheDefaultsMatchEigen) {
  const fs::path dir = test::scratch_dir("distributed-elasticity-options");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  const std::string c = "solve " + kCases[3] + " --json -o ";
  const fs::path eigen = dir / "eigen.vtu";
  const auto e = run_volmesh(c + eigen.string() + " --solver eigen", dir);
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const std::vector<std::pair<std::string, std::string>> options{
      {"-pc_hypre_boomeramg_vec_interp_variant 3", "cg+boomeramg"}, {"-pc_type gamg", "cg+gamg"}};
  for (const auto& [option, method] : options) {
    SCOPED_TRACE(option);
    const fs::path out = dir / "petsc.pvtu";  // the serial PETSc solve writes one piece
    const auto p = run_volmesh(c + out.string() + " --solver petsc " + option, dir);
    ASSERT_EQ(p.exit_code, 0) << p.err;
    EXPECT_EQ(nlohmann::json::parse(p.out)["linear_solver"], method);
    expect_same_solution(compare_files(eigen, out));
  }
}

// BoomerAMG's iterations stay about flat where incomplete Cholesky's double with each level
// (levels 4-6 here: 8 times the unknowns per level).
TEST_F(CliDistributed, IterationsStayFlatUnderRefinement) {
  const fs::path dir = test::scratch_dir("distributed-iterations");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  std::vector<int> iterations;
  for (int level : {4, 5, 6}) {
    const auto r = run_volmesh("solve poisson --problem sine --method cutcell --domain "
                               "builtin:ball --solver petsc --json --level " +
                                   std::to_string(level) + " -o " + (dir / "u.vtu").string(),
                               dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    iterations.push_back(nlohmann::json::parse(r.out)["iterations"]);
  }
  // Flat: every level within 20% of the levels' mean (V-cycles with Gauss-Seidel take 6, 8, 9).
  const double mean = (iterations[0] + iterations[1] + iterations[2]) / 3.0;
  for (int n : iterations)
    EXPECT_LE(std::abs(n - mean), kFlatIterations * mean)
        << iterations[0] << " " << iterations[1] << " " << iterations[2];
}

TEST_F(CliDistributed, StudySlopeIsTheSameOnTwoRanks) {
  const fs::path dir = test::scratch_dir("distributed-study");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  const std::string study = "study convergence --problem sine --method cutcell --domain "
                            "builtin:ball --levels 2..4 --json -o ";
  const auto serial = run_volmesh(study + (dir / "serial").string() + " --solver eigen", dir);
  ASSERT_EQ(serial.exit_code, 0) << serial.err;
  const auto two = run_volmesh(study + (dir / "two").string() + " --np 2", dir);
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const auto a = nlohmann::json::parse(serial.out)["series"][0]["slope"];
  const auto b = nlohmann::json::parse(two.out)["series"][0]["slope"];
  ASSERT_FALSE(a.empty()) << serial.out;
  for (const auto& [norm, slope] : a.items()) {
    if (slope.is_null()) continue;
    EXPECT_NEAR(slope.get<double>(), b[norm].get<double>(), 1e-6) << norm;
  }
}

TEST_F(CliDistributed, BadSetUpsGiveOneLineOnEveryRankCount) {
  const fs::path dir = test::scratch_dir("distributed-bad");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  // A grid at level 0 is one cell.
  expect_one_error(run_mpi(2, "solve poisson --problem sine --method grid --level 0 -o " +
                                  (dir / "u.pvtu").string(),
                           dir),
                   "2 ranks for a mesh of 1 cells");
  // Rank 0's own failure (a mesh file that does not exist) stops the others too.
  expect_one_error(run_mpi(2, "solve poisson --problem sine --mesh " + (dir / "none.vtu").string() +
                                  " -o " + (dir / "u.pvtu").string(),
                           dir),
                   "none.vtu");
  // A PETSc option PETSc refuses, on one and two ranks.
  for (int ranks : {1, 2})
    expect_one_error(run_mpi(ranks, "solve poisson --problem sine --method grid --level 3 -o " +
                                        (dir / "u.pvtu").string() + " -pc_type no-such-pc",
                             dir),
                     "PETSc");
  EXPECT_FALSE(fs::exists(dir / "u.pvtu"));
}

// A partitioned mesh that does not fit the run: one line from rank 0, every rank non-zero.
TEST_F(CliDistributed, BadPartitionedMeshesGiveOneLine) {
  const fs::path dir = test::scratch_dir("distributed-bad-pieces");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  const fs::path whole = dir / "mesh.vtu", u = dir / "u.pvtu";
  ASSERT_EQ(run_volmesh("mesh grid builtin:box --level 2 -o " + whole.string(), dir).exit_code, 0);
  for (const char* parts : {"1", "2"})
    ASSERT_EQ(run_volmesh("partition " + whole.string() + " --parts " + parts + " -o " +
                              (dir / ("p" + std::string(parts) + ".pvtu")).string() + " --quiet",
                          dir)
                  .exit_code,
              0);
  // The pieces of another mesh.
  const fs::path finer = dir / "finer.vtu";
  ASSERT_EQ(run_volmesh("mesh grid builtin:box --level 3 -o " + finer.string(), dir).exit_code, 0);
  ASSERT_EQ(run_volmesh("partition " + finer.string() + " --parts 2 -o " +
                            (dir / "r2.pvtu").string() + " --quiet",
                        dir)
                .exit_code,
            0);
  const auto summary = [&](const std::string& name, const std::string& from,
                           const std::string& to) {
    std::string text = test::slurp(dir / "p2.pvtu");
    text.replace(text.find(from), from.size(), to);
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  const std::string solve = "solve poisson --problem sine --mesh ";
  const std::string out = " -o " + u.string();
  expect_one_error(run_mpi(2, solve + (dir / "p1.pvtu").string() + out, dir),
                   "p1.pvtu: 1 pieces for 2 ranks");
  expect_one_error(run_mpi(1, solve + (dir / "p2.pvtu").string() + out, dir),
                   "p2.pvtu: 2 pieces for 1 ranks");
  expect_one_error(run_mpi(2, solve + summary("missing.pvtu", "p2/p2_1.vtu", "p2/p2_9.vtu") + out, dir),
                   "p2_9.vtu: cannot open");
  expect_one_error(run_mpi(2, solve + summary("mixed.pvtu", "p2/p2_1.vtu", "r2/r2_1.vtu") + out, dir),
                   "mixed.pvtu: ");
  // A solution's pieces carry global_cell/global_point, not the partition's ids.
  ASSERT_EQ(run_mpi(2, solve + whole.string() + " -o " + (dir / "solved.pvtu").string(), dir).exit_code, 0);
  expect_one_error(run_mpi(2, solve + (dir / "solved.pvtu").string() + out, dir),
                   "solved_0.vtu: no point data 'GlobalPointIds'");
  EXPECT_FALSE(fs::exists(u));
}

}  // namespace
}  // namespace volmesh
