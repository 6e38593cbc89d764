#include "volmesh/hexdc/qef.hpp"

#include <Eigen/SVD>
#include <stdexcept>

namespace volmesh {

QefVertex solve_qef(std::span<const EdgeCrossing> crossings, const Eigen::AlignedBox3d& node) {
  if (crossings.empty()) throw std::invalid_argument("solve_qef: no edge crossings");
  const auto n = static_cast<Eigen::Index>(crossings.size());

  Vec3 mass = Vec3::Zero();
  for (const EdgeCrossing& c : crossings) mass += c.point;
  mass /= static_cast<double>(n);

  // Rows nᵢᵀ and right-hand sides nᵢ · (pᵢ − m): the system about the mass point, so that
  // the dropped directions leave x at m.
  // Dynamic columns: Eigen computes a thin U only for those.
  Eigen::MatrixXd a(n, 3);
  Eigen::VectorXd r(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const EdgeCrossing& c = crossings[static_cast<std::size_t>(i)];
    a.row(i) = c.normal.transpose();
    r(i) = c.normal.dot(c.point - mass);
  }

  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();  // descending
  const Eigen::VectorXd ut_r = svd.matrixU().transpose() * r;
  Vec3 offset = Vec3::Zero();
  int rank = 0;
  for (Eigen::Index k = 0; k < sigma.size(); ++k) {
    if (sigma(k) <= kQefSingularCutoff * sigma(0)) break;
    offset += svd.matrixV().col(k) * (ut_r(k) / sigma(k));
    ++rank;
  }

  const Vec3 point = mass + offset;
  const double slack = kQefBoxTolerance * node.diagonal().norm();
  const Eigen::AlignedBox3d grown(node.min().array() - slack, node.max().array() + slack);
  if (!grown.contains(point)) return {mass, rank, true};
  return {point, rank, false};
}

}  // namespace volmesh
