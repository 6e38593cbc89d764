#include "volmesh/fem/linear_solver.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <chrono>
#include <stdexcept>
#include <string>

#include "petsc_solve.hpp"
#include "volmesh/fem/parallel.hpp"

namespace volmesh::fem {
namespace {

using Matrix = Eigen::SparseMatrix<double>;
using Clock = std::chrono::steady_clock;

double relative_residual(const Matrix& a, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  const double nb = b.norm();
  const double nr = (b - a.selfadjointView<Eigen::Lower>() * x).norm();
  return nb > 0.0 ? nr / nb : nr;
}

Eigen::VectorXd solve_direct(const Matrix& a, const Eigen::VectorXd& b,
                             LinearSolveReport& report) {
  const auto start = Clock::now();
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower> ldlt(a);
  if (ldlt.info() != Eigen::Success)
    throw std::runtime_error("sparse LDLT factorisation failed: the matrix is singular");
  if ((ldlt.vectorD().array() <= 0.0).any())
    throw std::runtime_error("the system matrix is not positive definite");
  report.preconditioner_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  report.method = "ldlt";
  report.iterations = 0;
  return ldlt.solve(b);
}

Eigen::VectorXd solve_cg(const Matrix& a, const Eigen::VectorXd& b,
                         const LinearSolverOptions& options, LinearSolveReport& report) {
  Eigen::ConjugateGradient<Matrix, Eigen::Lower,
                           Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>>
      cg;
  cg.setTolerance(options.tolerance);
  cg.setMaxIterations(options.max_iterations);
  const auto start = Clock::now();
  cg.compute(a);
  if (cg.info() != Eigen::Success)
    throw std::runtime_error("incomplete Cholesky preconditioner failed");
  report.preconditioner_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  Eigen::VectorXd x = cg.solve(b);
  report.method = "cg+ichol";
  report.iterations = static_cast<int>(cg.iterations());
  if (cg.info() != Eigen::Success)
    throw std::runtime_error("CG did not converge in " + std::to_string(cg.iterations()) +
                             " iterations (relative residual " + std::to_string(cg.error()) +
                             ")");
  return x;
}

bool use_petsc(const LinearSolverOptions& options, Index unknowns) {
  using Backend = LinearSolverOptions::Backend;
  if (options.backend == Backend::petsc && !petsc_built())
    throw std::runtime_error(
        "the PETSc solver was asked for, and this volmesh was built without PETSc");
  return options.backend == Backend::petsc ||
         (options.backend == Backend::automatic && petsc_built() &&
          unknowns > options.petsc_limit);
}

// This process alone solves the whole system (the distributed path is fe_distributed.cpp).
// The conversion to PETSc's rows counts as assembly.
Eigen::VectorXd solve_petsc(const Matrix& a, const Eigen::VectorXd& b,
                            const LinearSolverOptions& options, LinearSolveReport& report,
                            const NodeLayout& layout) {
  // Starting MPI and PETSc in a serial run is set-up.
  const auto starting = Clock::now();
  start_petsc();
  report.setup_seconds += std::chrono::duration<double>(Clock::now() - starting).count();
  const auto start = Clock::now();
  detail::OwnedRows rows = detail::owned_rows_of(a, b);
  rows.block_size = layout.components;
  if (layout.components == 3 && layout.points) {
    rows.coordinates.reserve(a.rows());
    for (const Vec3& p : *layout.points) rows.coordinates.insert(rows.coordinates.end(), {p.x(), p.y(), p.z()});
  }
  report.assembly_seconds += std::chrono::duration<double>(Clock::now() - start).count();
  return detail::petsc_solve_spd(rows, options, report);
}

}  // namespace

Eigen::VectorXd solve_spd(const Matrix& a, const Eigen::VectorXd& b,
                          const LinearSolverOptions& options, LinearSolveReport& report,
                          const NodeLayout& layout) {
  const auto start = Clock::now();
  report.unknowns = static_cast<Index>(a.rows());
  report.preconditioner_seconds = 0.0;
  const double assembly_before = report.assembly_seconds, setup_before = report.setup_seconds;
  Eigen::VectorXd x;
  if (a.rows() == 0) {
    x.resize(0);
    report.method = "none";
  } else {
    const bool direct =
        options.kind == LinearSolverOptions::Kind::direct ||
        (options.kind == LinearSolverOptions::Kind::automatic &&
         options.backend != LinearSolverOptions::Backend::petsc && a.rows() <= options.direct_limit);
    x = direct                       ? solve_direct(a, b, report)
        : use_petsc(options, report.unknowns) ? solve_petsc(a, b, options, report, layout)
                                     : solve_cg(a, b, options, report);
  }
  report.residual = a.rows() ? relative_residual(a, x, b) : 0.0;
  report.solve_seconds = std::chrono::duration<double>(Clock::now() - start).count() -
                         report.preconditioner_seconds -
                         (report.assembly_seconds - assembly_before) -
                         (report.setup_seconds - setup_before);
  return x;
}

Eigen::VectorXd solve_spd_constrained(const Matrix& a, const Eigen::VectorXd& b,
                                      const std::vector<char>& fixed,
                                      const Eigen::VectorXd& fixed_values,
                                      const LinearSolverOptions& options,
                                      LinearSolveReport& report, const NodeLayout& layout) {
  const auto start = Clock::now();
  const Index n = static_cast<Index>(a.rows());
  std::vector<Index> free_index(n, kNoIndex);
  Index free_count = 0;
  for (Index i = 0; i < n; ++i)
    if (!fixed[i]) free_index[i] = free_count++;

  // Only the lower triangle of `a` is read (as by the solvers), so each off-diagonal
  // coupling is seen once and moved to both right-hand sides it affects.
  Eigen::VectorXd rhs(free_count);
  for (Index i = 0; i < n; ++i)
    if (!fixed[i]) rhs[free_index[i]] = b[i];
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(a.nonZeros());
  for (Index col = 0; col < n; ++col)
    for (Matrix::InnerIterator it(a, col); it; ++it) {
      const Index row = static_cast<Index>(it.row());
      if (row < col) continue;
      const bool row_free = !fixed[row], col_free = !fixed[col];
      if (row_free && col_free)
        entries.emplace_back(free_index[row], free_index[col], it.value());
      else if (row_free)
        rhs[free_index[row]] -= it.value() * fixed_values[col];
      else if (col_free)
        rhs[free_index[col]] -= it.value() * fixed_values[row];
    }
  Matrix reduced(free_count, free_count);
  reduced.setFromTriplets(entries.begin(), entries.end());
  entries = {};
  const double eliminated = std::chrono::duration<double>(Clock::now() - start).count();
  // The free nodes' points in the reduced order: a node's unknowns are fixed together.
  std::vector<Vec3> free_points;
  if (layout.points) {
    for (Index i = 0; i < n; i += layout.components)
      if (!fixed[i]) free_points.push_back((*layout.points)[i / layout.components]);
  }
  const Eigen::VectorXd y = solve_spd(reduced, rhs, options, report,
                                      {layout.components, layout.points ? &free_points : nullptr});

  Eigen::VectorXd x(n);
  for (Index i = 0; i < n; ++i) x[i] = fixed[i] ? fixed_values[i] : y[free_index[i]];
  report.assembly_seconds += eliminated;
  return x;
}

}  // namespace volmesh::fem
