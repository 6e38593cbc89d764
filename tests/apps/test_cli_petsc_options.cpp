// Where PETSc's options go on volmesh's command line: after the subcommand's own arguments or
// after "--", where they reach PETSc; anywhere else they are refused with one line that says
// where they belong (exit 2) and nothing is written.
#include <gtest/gtest.h>

#include <string>

#include "run_mpi.hpp"

namespace volmesh {
namespace {

namespace fs = std::filesystem;

// PETSc's solves start MPI: its leaks past finalize are suppressed as for the mpirun tests.
class CliPetscOptions : public test::MpiTest {};
using test::petsc_built;
using test::run_volmesh;

const std::string kWhere = "PETSc options go after the subcommand's own arguments, or after --";

TEST_F(CliPetscOptions, APetscOptionBeforeTheArgumentsIsRefusedWithWhereItGoes) {
  const fs::path dir = test::scratch_dir("petsc-options-refused");
  const fs::path out = dir / "x.vtu";
  const std::string problem = "--problem sine --method grid --domain builtin:box --level 3 "
                              "--solver petsc -o " + out.string();
  for (const std::string& args :
       {"solve -ksp_monitor poisson " + problem,             // before the subcommand's argument
        "solve poisson -ksp_rtol 1e-3 " + problem,           // among its options
        "solve poisson " + problem + " -ksp_monitor --json"}) {  // before one of volmesh's
    SCOPED_TRACE(args);
    const auto r = run_volmesh(args, dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(kWhere), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST_F(CliPetscOptions, PetscOptionsAtTheEndOrAfterTwoDashesReachPetsc) {
  const fs::path dir = test::scratch_dir("petsc-options-placed");
  if (!petsc_built(dir)) GTEST_SKIP() << "built without PETSc";
  const fs::path out = dir / "x.vtu";
  const std::string solve = "solve poisson --problem sine --method grid --domain builtin:box "
                            "--level 3 --solver petsc -o " + out.string();
  for (const char* options : {" -ksp_monitor", " -- -ksp_monitor"}) {
    SCOPED_TRACE(options);
    fs::remove(out);
    const auto r = run_volmesh(solve + options, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // PETSc's monitor prints CG's residual at every iteration.
    EXPECT_NE(r.out.find("KSP Residual norm"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(out));
  }
}

}  // namespace
}  // namespace volmesh
