// The SPD solvers on the 7-point Laplacian of a cube grid: both paths agree with each other
// and reproduce a known solution; eliminating fixed values gives the constrained solution.
#include <gtest/gtest.h>

#include <vector>

#include "volmesh/fem/linear_solver.hpp"

namespace volmesh::fem {
namespace {

using Matrix = Eigen::SparseMatrix<double>;

Matrix laplacian(int n) {
  const auto id = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int r = id(i, j, k);
        t.emplace_back(r, r, 6.0);
        if (i > 0) t.emplace_back(r, id(i - 1, j, k), -1.0);
        if (i + 1 < n) t.emplace_back(r, id(i + 1, j, k), -1.0);
        if (j > 0) t.emplace_back(r, id(i, j - 1, k), -1.0);
        if (j + 1 < n) t.emplace_back(r, id(i, j + 1, k), -1.0);
        if (k > 0) t.emplace_back(r, id(i, j, k - 1), -1.0);
        if (k + 1 < n) t.emplace_back(r, id(i, j, k + 1), -1.0);
      }
  Matrix a(n * n * n, n * n * n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

TEST(LinearSolver, DirectAndCgReproduceAKnownSolution) {
  const Matrix a = laplacian(12);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);
  const Eigen::VectorXd b = a * x;
  for (auto kind : {LinearSolverOptions::Kind::direct, LinearSolverOptions::Kind::cg}) {
    LinearSolverOptions options;
    options.kind = kind;
    LinearSolveReport report;
    const Eigen::VectorXd y = solve_spd(a, b, options, report);
    EXPECT_LT((y - x).lpNorm<Eigen::Infinity>(), 1e-8) << report.method;
    EXPECT_LT(report.residual, 1e-10) << report.method;
    EXPECT_EQ(report.unknowns, a.rows());
    if (kind == LinearSolverOptions::Kind::cg) {
      EXPECT_EQ(report.method, "cg+ichol");
      EXPECT_GT(report.iterations, 0);
      EXPECT_LT(report.iterations, 60);  // ichol keeps a 1728-unknown Laplacian far below n
    } else {
      EXPECT_EQ(report.method, "ldlt");
    }
  }
}

TEST(LinearSolver, EliminatedValuesGiveTheConstrainedSolution) {
  const Matrix a = laplacian(8);
  const Index n = static_cast<Index>(a.rows());
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, 0.5, 3.0).array().sin();
  std::vector<char> fixed(n, 0);
  for (Index i = 0; i < n; i += 3) fixed[i] = 1;
  // Right-hand side that x satisfies on the free rows; fixed rows carry garbage to prove they
  // are ignored.
  Eigen::VectorXd b = a * x;
  for (Index i = 0; i < n; ++i)
    if (fixed[i]) b[i] = 1e6;
  for (auto kind : {LinearSolverOptions::Kind::direct, LinearSolverOptions::Kind::cg}) {
    LinearSolverOptions options;
    options.kind = kind;
    LinearSolveReport report;
    const Eigen::VectorXd y = solve_spd_constrained(a, b, fixed, x, options, report);
    EXPECT_LT((y - x).lpNorm<Eigen::Infinity>(), 1e-8) << report.method;
    EXPECT_EQ(report.unknowns, n - (n + 2) / 3);
  }
}

TEST(LinearSolver, IndefiniteMatrixIsRefused) {
  Matrix a(2, 2);
  a.insert(0, 0) = 1.0;
  a.insert(1, 1) = -1.0;
  LinearSolverOptions options;
  options.kind = LinearSolverOptions::Kind::direct;
  LinearSolveReport report;
  EXPECT_THROW(solve_spd(a, Eigen::VectorXd::Ones(2), options, report), std::runtime_error);
}

TEST(LinearSolver, CgReportsNonConvergence) {
  const Matrix a = laplacian(10);
  LinearSolverOptions options;
  options.kind = LinearSolverOptions::Kind::cg;
  options.max_iterations = 2;
  LinearSolveReport report;
  EXPECT_THROW(solve_spd(a, Eigen::VectorXd::Ones(a.rows()), options, report),
               std::runtime_error);
}

}  // namespace
}  // namespace volmesh::fem
