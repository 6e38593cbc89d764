#pragma once
// --solver auto|eigen|petsc, the option of `solve` and `study` (solve_setup.hpp).
#include "volmesh/runs/solve_setup.hpp"

namespace CLI {
class App;
}

namespace volmesh::cli {

void add_solver_option(CLI::App& app, SolverBackend& backend);

}  // namespace volmesh::cli
