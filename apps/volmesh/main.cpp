// volmesh: one binary, subcommands (docs/architecture.md). Exit codes: 0 success, 2 bad usage,
// 1 bad input or failure with one line on stderr.
#include <CLI/CLI.hpp>
#include <iostream>
#include <new>
#include <vector>

#include "commands.hpp"
#include "volmesh/runs/allocator.hpp"
#include "volmesh/runs/distributed.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/fem/parallel.hpp"
#include "volmesh/meshers/registry.hpp"
#include "volmesh/octree_dist/distributed_octree.hpp"

int main(int argc, char** argv) {
  using namespace volmesh;
  cli::keep_freed_memory();
  // Takes PETSc's options off the command line before CLI11 sees it; PETSc stops when it ends.
  fem::Session session(argc, argv);
  if (!fem::petsc_options_misplaced().empty()) {
    if (fem::rank() == 0) std::cerr << "volmesh: error: " << fem::petsc_options_misplaced() << "\n";
    return 2;
  }
  if (!fem::petsc_built() && !fem::petsc_arguments().empty()) {
    std::cerr << "volmesh: error: " << fem::petsc_arguments().front()
              << " is a PETSc option, and this volmesh was built without PETSc\n";
    return 2;
  }
  cli::remember_command_line(argc, argv);
  CLI::App app{"volmesh — volume meshing (" + meshers::mesher_names() +
               "), checking, partitioning, Poisson and elasticity solves, export"};
  app.set_version_flag("--version",
                       std::string("volmesh ") + VOLMESH_VERSION + "\n" + fem::backend_summary() + "\n" +
                           distributed_octree_summary());
  app.require_subcommand(1);
  std::vector<cli::Command> commands{
      cli::add_info_command(app),      cli::add_convert_command(app), cli::add_check_command(app),
      cli::add_demo_command(app),      cli::add_sdf_command(app),     cli::add_mesh_command(app),
      cli::add_partition_command(app), cli::add_solve_command(app),   cli::add_study_command(app),
      cli::add_improve_command(app)};
  // After the subcommands, which would otherwise inherit it.
  app.footer(R"(Examples:
  volmesh demo                                       the main job on built-in data
  volmesh mesh cutcell builtin:primitives --level 5 -o primitives.vtu
  volmesh check primitives.vtu --surface builtin:primitives
  volmesh convert primitives.vtu primitives.msh --decompose tets
  volmesh solve poisson --problem sine --method cutcell --level 4 -o u.vtu
  volmesh study convergence --problem sine --methods staircase,cutcell --levels 2..5 -o study
Each subcommand's --help has its own examples.)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  try {
    for (auto& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const std::bad_alloc&) {
    std::cerr << "volmesh: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    // An error the ranks agreed on (fem::agree) is thrown on every rank; rank 0 speaks for them.
    if (fem::rank() == 0) std::cerr << "volmesh: error: " << e.what() << "\n";
    return 1;
  }
  return 2;
}
