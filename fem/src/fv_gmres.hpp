#pragma once
// Restarted GMRES for a linear operator given as a function, used to accelerate the
// deferred non-orthogonal correction (fv_solve.cpp).
#include <functional>

#include <Eigen/Core>

namespace volmesh::fem {

using LinearMap = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

struct GmresResult {
  int applications = 0;   // calls of `apply` and `residual` together
  double relative = 0.0;  // last residual norm / norm of x
  bool converged = false;
};

// Solves T x = z from the given x. `residual(x)` returns z − T x, `apply(v)` returns T v.
// Each restart cycle of `restart` Arnoldi steps begins with a true residual; stops there when
// its norm is at most tolerance · ‖x‖ or max_applications calls have been made.
GmresResult gmres(const LinearMap& apply, const LinearMap& residual, Eigen::VectorXd& x,
                  int restart, int max_applications, double tolerance);

}  // namespace volmesh::fem
