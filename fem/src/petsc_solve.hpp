#pragma once
// The PETSc backend: CG preconditioned by hypre's BoomerAMG on a symmetric positive definite
// system whose rows are spread over the ranks, each rank holding a contiguous block of
// global rows. PETSc's headers stay in petsc_solve.cpp.
#include <Eigen/Core>
#include <vector>

#include "volmesh/core/types.hpp"
#include "volmesh/fem/linear_solver.hpp"

namespace volmesh::fem::detail {

// This rank's rows [first, first + rows) of a global system of `global` rows, whole rows
// (both triangles) in CSR with global, increasing column indices.
struct OwnedRows {
  Index first = 0;
  Index global = 0;
  std::vector<Index> offsets{0};  // per owned row, then the end
  std::vector<Index> columns;
  std::vector<double> values;
  Eigen::VectorXd rhs;  // the owned rows' right-hand side
  // Unknowns per node (3 for elasticity, node-major); with block_size 3 and `coordinates`
  // (x, y, z of each owned node) the rigid-body modes are given to the preconditioner.
  int block_size = 1;
  std::vector<double> coordinates;
  // Rows spread over all ranks (PETSC_COMM_WORLD), or this rank's own whole system.
  bool distributed = false;
};

// The owned part of the solution. Collective over the ranks. Fills report (method,
// iterations, residual over all ranks, preconditioner and solve seconds). Throws
// std::runtime_error when CG does not converge or PETSc fails (hypre missing, ...).
Eigen::VectorXd petsc_solve_spd(const OwnedRows& rows, const LinearSolverOptions& options,
                                LinearSolveReport& report);

// The whole system of one rank from the lower triangle `a` (the serial path).
OwnedRows owned_rows_of(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& rhs);

}  // namespace volmesh::fem::detail
