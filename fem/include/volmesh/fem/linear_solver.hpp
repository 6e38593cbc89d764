#pragma once
// Sparse symmetric positive definite systems: conjugate gradients preconditioned by an
// incomplete Cholesky factorisation (Eigen's IncompleteCholesky with AMD ordering and its
// automatic diagonal shift), or a sparse LDLᵀ factorisation for small systems.
#include <vector>

#include <Eigen/SparseCore>

#include "volmesh/fem/solution.hpp"

namespace volmesh::fem {

struct LinearSolverOptions {
  enum class Kind { automatic, cg, direct };
  Kind kind = Kind::automatic;  // automatic: direct up to direct_limit unknowns, else CG
  Index direct_limit = 20000;
  double tolerance = 1e-10;     // on ‖b − Ax‖ / ‖b‖
  int max_iterations = 20000;
};

// Only the lower triangle of `a` is read, so a full symmetric matrix and its lower half give
// the same result. Throws std::runtime_error when CG does not reach the tolerance or the factorisation fails
// (the matrix is not SPD: a mesh or a problem the discretisation cannot handle).
Eigen::VectorXd solve_spd(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b,
                          const LinearSolverOptions& options, LinearSolveReport& report);

// A symmetric system with some unknowns fixed (Dirichlet values): the rows and columns of the
// fixed unknowns are eliminated, the rest solved by solve_spd, the fixed values put back.
Eigen::VectorXd solve_spd_constrained(const Eigen::SparseMatrix<double>& a,
                                      const Eigen::VectorXd& b,
                                      const std::vector<char>& fixed,
                                      const Eigen::VectorXd& fixed_values,
                                      const LinearSolverOptions& options,
                                      LinearSolveReport& report);

}  // namespace volmesh::fem
