// The finite-volume Poisson solve: the two-point system, deferred non-orthogonal correction,
// errors against the exact solution.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fv_gmres.hpp"
#include "fv_system.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/fem/finite_volume.hpp"

namespace volmesh::fem {
namespace {

// Where the stages start, as rough fractions of the run (LinearSolverOptions::progress).
constexpr double kLinearSolveStart = 0.3;
constexpr double kCorrectionStart = 0.4;
constexpr double kResultsStart = 0.9;

Eigen::VectorXd solve_counted(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b,
                              const LinearSolverOptions& options, LinearSolveReport& total) {
  LinearSolveReport step;
  Eigen::VectorXd x = solve_spd(a, b, options, step);
  total.method = step.method;
  total.iterations += step.iterations;
  total.preconditioner_seconds += step.preconditioner_seconds;
  return x;
}

// Sums in cell order: the same bytes for any thread count.
ErrorNorms fv_errors(const PolyMesh& mesh, const FvSystem& s, const PoissonProblem& problem,
                     const Eigen::VectorXd& u, const std::vector<Vec3>& g) {
  const Index nc = mesh.num_cells();
  std::vector<double> value_error(nc), gradient_error(nc, 0.0);
  tbb::parallel_for(Index{0}, nc, [&](Index c) {
    const Vec3& x = s.geometry.cells[c].centre;
    value_error[c] = problem.exact(x) - u[c];
    if (problem.exact_gradient)
      gradient_error[c] = (problem.exact_gradient(x) - g[c]).squaredNorm();
  });
  ErrorNorms e;
  double l2 = 0.0, linf = 0.0, h1 = 0.0;
  for (Index c = 0; c < nc; ++c) {
    const double volume = s.geometry.cells[c].volume;
    l2 += volume * value_error[c] * value_error[c];
    linf = std::max(linf, std::abs(value_error[c]));
    h1 += volume * gradient_error[c];
  }
  e.l2 = std::sqrt(l2);
  e.linf = linf;
  if (problem.exact_gradient) e.h1 = std::sqrt(h1);
  return e;
}

}  // namespace

ScalarSolution solve_poisson_fv(const PolyMesh& mesh, const PoissonProblem& problem,
                                const LinearSolverOptions& solver, const FvOptions& options,
                                FvReport* report) {
  const auto start = Clock::now();
  volmesh::report(solver.progress, "assembly", 0.0);
  const FvSystem s = build_fv_system(mesh, problem, options.non_orthogonal_correction);
  const Eigen::SparseMatrix<double> a = fv_matrix(mesh, s);
  const auto a_times = [&a](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    return a.selfadjointView<Eigen::Lower>() * v;
  };
  const Eigen::VectorXd base = fv_base_rhs(mesh, s, problem);

  ScalarSolution solution;
  solution.dofs = mesh.num_cells();
  LinearSolveReport& total = solution.solve;
  total.assembly_seconds = seconds_since(start);
  total.unknowns = mesh.num_cells();

  FvReport local;
  FvReport& r = report ? *report : local;
  r = FvReport{};
  // The correction solves the same matrix a dozen times or more: solve_spd refactorises on
  // every call, and a sparse LDLᵀ of a 3D mesh costs seconds at 10⁴ cells (measured: 3 s at
  // 15,000 cells) where incomplete-Cholesky CG costs tens of milliseconds. The inner solves
  // are as tight as the outer tolerance so that GMRES can reach it.
  LinearSolverOptions inner = solver;
  if (s.non_orthogonal && solver.kind == LinearSolverOptions::Kind::automatic) {
    inner.kind = LinearSolverOptions::Kind::cg;
    inner.tolerance = std::min(solver.tolerance, options.correction_tolerance);
  }
  volmesh::report(solver.progress, "linear solve", kLinearSolveStart);
  const Clock::time_point solving = Clock::now();
  Eigen::VectorXd u = solve_counted(a, base, inner, total);
  // The corrected equations A u = b + K u + k (K u + k: the correction fluxes of u's
  // gradients) preconditioned by the two-point matrix: (I − A⁻¹K) u = A⁻¹(b + k). Plain
  // deferred correction is the Richardson iteration on this system; on meshes with sliver
  // cut cells its iteration matrix A⁻¹K has eigenvalues beyond 1 (measured: −1.25 on a plane
  // cut through an 8³ grid) and it diverges, so GMRES accelerates it.
  if (s.non_orthogonal) {
    volmesh::report(solver.progress, "non-orthogonal correction", kCorrectionStart);
    const LinearMap defect = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      const Eigen::VectorXd rhs = base + fv_correction(mesh, s, fv_gradients(mesh, s, v));
      return solve_counted(a, rhs - a_times(v), inner, total);
    };
    const LinearMap apply = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      const Eigen::VectorXd k = fv_correction(mesh, s, fv_gradients(mesh, s, v, false));
      return v - solve_counted(a, k, inner, total);
    };
    const GmresResult g = gmres(apply, defect, u, options.restart, options.max_corrections,
                                options.correction_tolerance);
    r.corrections = g.applications;
    r.last_change = g.relative;
    r.converged = g.converged;
    if (!std::isfinite(g.relative))
      throw std::runtime_error("finite volumes: the non-orthogonal correction diverged");
  }
  // The correction's fluxes and GMRES count as solving, the factorisations apart.
  total.solve_seconds = seconds_since(solving) - total.preconditioner_seconds;
  volmesh::report(solver.progress, "results", kResultsStart);
  const Clock::time_point results = Clock::now();
  const std::vector<Vec3> gradients = fv_gradients(mesh, s, u);
  Eigen::VectorXd rhs = base;
  if (s.non_orthogonal) rhs += fv_correction(mesh, s, gradients);
  const double rhs_norm = rhs.norm(), defect_norm = (rhs - a_times(u)).norm();
  total.residual = rhs_norm > 0.0 ? defect_norm / rhs_norm : defect_norm;

  solution.cell_values.assign(u.data(), u.data() + u.size());
  if (problem.exact) solution.errors = fv_errors(mesh, s, problem, u, gradients);
  r.cell_gradients = gradients;
  total.errors_seconds = seconds_since(results);
  return solution;
}

}  // namespace volmesh::fem
