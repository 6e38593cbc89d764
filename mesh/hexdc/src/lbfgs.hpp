#pragma once
// The L-BFGS two-loop recursion (Nocedal and Wright, Algorithm 7.4): a quasi-Newton direction
// from the last few steps and gradient changes, without a matrix.
#include <deque>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace volmesh::hexdc_detail {

class Lbfgs {
 public:
  explicit Lbfgs(std::size_t memory) : memory_(memory) {}

  void reset() { pairs_.clear(); }

  // A step s and its gradient change y; a pair without positive curvature is skipped (it would
  // make the inverse Hessian indefinite).
  void push(Eigen::VectorXd s, Eigen::VectorXd y) {
    const double sy = s.dot(y);
    if (!(sy > kMinCurvature * s.norm() * y.norm())) return;
    if (pairs_.size() == memory_) pairs_.pop_front();
    pairs_.push_back({std::move(s), std::move(y), 1.0 / sy});
  }

  // −H g, H the inverse Hessian estimate (the last pair's s·y / y·y times I before the pairs).
  Eigen::VectorXd direction(const Eigen::VectorXd& g) const {
    Eigen::VectorXd q = -g;
    std::vector<double> alpha(pairs_.size());
    for (std::size_t i = pairs_.size(); i-- > 0;) {
      alpha[i] = pairs_[i].rho * pairs_[i].s.dot(q);
      q -= alpha[i] * pairs_[i].y;
    }
    if (!pairs_.empty()) q *= 1.0 / (pairs_.back().rho * pairs_.back().y.squaredNorm());
    for (std::size_t i = 0; i < pairs_.size(); ++i) {
      const double beta = pairs_[i].rho * pairs_[i].y.dot(q);
      q += (alpha[i] - beta) * pairs_[i].s;
    }
    return q;
  }

  bool empty() const { return pairs_.empty(); }

 private:
  // s·y below this fraction of |s| |y| counts as no curvature.
  static constexpr double kMinCurvature = 1e-10;
  struct Pair {
    Eigen::VectorXd s, y;
    double rho;
  };
  std::size_t memory_;
  std::deque<Pair> pairs_;
};

}  // namespace volmesh::hexdc_detail
