#include "fv_gmres.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace volmesh::fem {

GmresResult gmres(const LinearMap& apply, const LinearMap& residual, Eigen::VectorXd& x,
                  int restart, int max_applications, double tolerance) {
  GmresResult result;
  for (;;) {
    const Eigen::VectorXd r = residual(x);
    ++result.applications;
    const double beta = r.norm(), scale = x.norm();
    result.relative = scale > 0.0 ? beta / scale : beta;
    result.converged = beta <= tolerance * scale;
    if (result.converged || !std::isfinite(beta) || result.applications >= max_applications)
      return result;
    // Arnoldi with modified Gram-Schmidt; Givens rotations keep the least-squares problem
    // upper triangular, so its residual is known at every step.
    std::vector<Eigen::VectorXd> basis{r / beta};
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(restart + 1, restart);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(restart + 1), cs(restart), sn(restart);
    g[0] = beta;
    int steps = 0;
    while (steps < restart && result.applications < max_applications) {
      const int j = steps;
      Eigen::VectorXd w = apply(basis[j]);
      ++result.applications;
      for (int i = 0; i <= j; ++i) {
        h(i, j) = w.dot(basis[i]);
        w -= h(i, j) * basis[i];
      }
      h(j + 1, j) = w.norm();
      for (int i = 0; i < j; ++i) {
        const double t = cs[i] * h(i, j) + sn[i] * h(i + 1, j);
        h(i + 1, j) = -sn[i] * h(i, j) + cs[i] * h(i + 1, j);
        h(i, j) = t;
      }
      const double rho = std::hypot(h(j, j), h(j + 1, j));
      cs[j] = rho > 0.0 ? h(j, j) / rho : 1.0;
      sn[j] = rho > 0.0 ? h(j + 1, j) / rho : 0.0;
      const double hj1 = h(j + 1, j);
      h(j, j) = rho;
      h(j + 1, j) = 0.0;
      g[j + 1] = -sn[j] * g[j];
      g[j] = cs[j] * g[j];
      ++steps;
      if (std::abs(g[j + 1]) <= tolerance * scale || hj1 == 0.0) break;
      basis.push_back(w / hj1);
    }
    const Eigen::VectorXd y = h.topLeftCorner(steps, steps)
                                  .triangularView<Eigen::Upper>()
                                  .solve(g.head(steps));
    for (int i = 0; i < steps; ++i) x += y[i] * basis[i];
  }
}

}  // namespace volmesh::fem
