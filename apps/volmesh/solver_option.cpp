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

CLI::Option* add_partition_option(CLI::App& app, std::string& partition) {
  return app.add_option("--partition", partition,
                        "under mpirun: octree (every rank meshes its piece and solves on it; the "
                        "default for cutcell, staircase and grid) or metis (rank 0 meshes, METIS "
                        "partitions, every rank holds the whole mesh)")
      ->check(CLI::IsMember({"metis", "octree"}));
}

}  // namespace volmesh::cli
