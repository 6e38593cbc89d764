#pragma once
// What a solver returns: the discrete solution where it lives, how the linear system went,
// and the errors against the exact solution when the problem has one.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "volmesh/core/types.hpp"

namespace volmesh::fem {

struct LinearSolveReport {
  std::string method;       // e.g. "cg+ichol", "ldlt"
  int iterations = 0;       // 0 for a direct solve
  double residual = 0.0;    // ‖b − Ax‖ / ‖b‖ at exit
  Index unknowns = 0;       // after eliminating Dirichlet values
  // Wall time of each stage of the solve; together they make up the whole of it.
  double setup_seconds = 0.0;           // the space, per-cell data, boundary conditions, Dirichlet values
  double assembly_seconds = 0.0;        // the global system, its natural loads, the elimination
  double preconditioner_seconds = 0.0;  // the incomplete Cholesky or LDLᵀ factorisation
  double solve_seconds = 0.0;           // the iterations (or triangular solves), the residual
  double errors_seconds = 0.0;          // the solution's values per point and cell, the error norms
};

struct ErrorNorms {
  double l2 = std::numeric_limits<double>::quiet_NaN();    // ‖u − u_h‖ over the mesh
  double linf = std::numeric_limits<double>::quiet_NaN();  // max at the nodes (cell centres for FV)
  double h1 = std::numeric_limits<double>::quiet_NaN();    // |u − u_h|_1 seminorm
};

struct ScalarSolution {
  std::vector<double> point_values;  // per mesh point (vertex values; empty for FV)
  std::vector<double> cell_values;   // per cell (cell average or centre value)
  Index dofs = 0;
  LinearSolveReport solve;
  std::optional<ErrorNorms> errors;
};

struct VectorSolution {
  std::vector<Vec3> point_values;    // displacement per mesh point
  std::vector<double> von_mises;     // per cell
  std::vector<Eigen::Matrix3d> cell_stress;  // per cell (mean over the cell)
  Index dofs = 0;
  LinearSolveReport solve;
  std::optional<ErrorNorms> errors;  // displacement errors
};

}  // namespace volmesh::fem
