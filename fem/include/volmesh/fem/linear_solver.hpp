#pragma once
// Sparse symmetric positive definite systems: conjugate gradients preconditioned by an
// incomplete Cholesky factorisation (Eigen's IncompleteCholesky with AMD ordering and its
// automatic diagonal shift), or a sparse LDLᵀ factorisation for small systems.
#include <vector>

#include <Eigen/SparseCore>

#include "volmesh/core/progress.hpp"
#include "volmesh/fem/solution.hpp"

namespace volmesh::fem {

struct LinearSolverOptions {
  enum class Kind { automatic, cg, direct };
  Kind kind = Kind::automatic;  // automatic: direct up to direct_limit unknowns, else CG
  // Measured (validation/fem/run.sh --solvers): Eigen's simplicial LDLᵀ fills in heavily on
  // 3D meshes, so CG with incomplete Cholesky is faster from about 1,000 unknowns on (P1
  // tets 12,167 unknowns: 0.17 s against 4.0 s; Q1 elasticity 5,184: 0.29 s against 2.1 s).
  // Below it the exact solve costs nothing.
  Index direct_limit = 1000;
  double tolerance = 1e-10;     // on ‖b − Ax‖ / ‖b‖
  int max_iterations = 20000;
  // The solves that take these options (solve_poisson, solve_elasticity, solve_poisson_fv)
  // report their stages here ("assembly", "linear solve", "results": the cell values and
  // errors) with rough fractions of their run; solve_spd ignores it.
  Progress progress;
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
