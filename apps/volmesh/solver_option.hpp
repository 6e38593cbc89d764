#pragma once
// The options of `solve` and `study` that choose how they solve: --solver auto|eigen|petsc
// (solve_setup.hpp) and --partition metis|octree (mesh_pieces.hpp).
#include <string>

#include "volmesh/runs/solve_setup.hpp"

namespace CLI {
class App;
class Option;
}

namespace volmesh::cli {

void add_solver_option(CLI::App& app, SolverBackend& backend);

// --partition metis|octree on `solve` and `study`; returns the option.
CLI::Option* add_partition_option(CLI::App& app, std::string& partition);

}  // namespace volmesh::cli
