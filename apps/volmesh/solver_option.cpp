#include "solver_option.hpp"

#include <CLI/CLI.hpp>

namespace volmesh::cli {

void add_solver_option(CLI::App& app, SolverBackend& backend) {
  app.add_option("--solver", backend,
                 "who solves the large systems: auto (PETSc CG + BoomerAMG when built with "
                 "PETSc, else Eigen), eigen (CG + incomplete Cholesky), petsc; PETSc's own "
                 "options (-ksp_*, -pc_*, -log_view) go after the subcommand's own arguments, "
                 "or after --")
      ->transform(CLI::CheckedTransformer(solver_backends()))
      ->default_str("auto");
}

}  // namespace volmesh::cli
