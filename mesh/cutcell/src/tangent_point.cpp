#include "volmesh/cutcell/tangent_point.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace volmesh::cutcell {

Vec3 tangent_intersection(std::span<const Vec3> points, std::span<const Vec3> normals,
                          int max_rank, double relative_cutoff) {
  Vec3 mass = Vec3::Zero();
  for (const Vec3& s : points) mass += s;
  return tangent_intersection(points, normals, Vec3(mass / static_cast<double>(points.size())),
                              max_rank, relative_cutoff);
}

Vec3 tangent_intersection(std::span<const Vec3> points, std::span<const Vec3> normals,
                          const Vec3& origin, int max_rank, double relative_cutoff) {
  const Vec3& mass = origin;
  // Normal equations A^T A x = A^T b with x = p - mass: the eigen-decomposition of the
  // symmetric A^T A is the SVD of A, and its truncated inverse A's pseudo-inverse.
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Vec3 atb = Vec3::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& n = normals[i];
    ata += n * n.transpose();
    atb += n * n.dot(points[i] - mass);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(ata);
  // Eigenvalues ascending; they are the squared singular values of A.
  const Vec3 sigma = eigen.eigenvalues();
  if (!(sigma[2] > 0.0)) return mass;
  const double cutoff = relative_cutoff * relative_cutoff * sigma[2];
  Vec3 x = Vec3::Zero();
  for (int k = 2; k > 2 - std::min(max_rank, 3); --k) {
    if (sigma[k] <= cutoff) break;
    const Vec3 v = eigen.eigenvectors().col(k);
    x += v * (v.dot(atb) / sigma[k]);
  }
  return mass + x;
}

std::optional<Feature> sharp_feature(std::span<const Vec3> points, std::span<const Vec3> normals,
                                     const FeatureThresholds& thresholds) {
  const std::size_t n = normals.size();
  double theta = 2.0;
  std::size_t i0 = 0, i1 = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (const double d = normals[i].dot(normals[j]); d < theta) {
        theta = d;
        i0 = i;
        i1 = j;
      }
  if (!(theta < thresholds.theta)) return std::nullopt;
  const Vec3 axis = normals[i0].cross(normals[i1]);
  double phi = 0.0;
  if (const double len = axis.norm(); len > 1e-12)
    for (const Vec3& m : normals) phi = std::max(phi, std::abs(m.dot(axis / len)));
  else
    phi = 1.0;  // opposite normals: a thin sheet, treat as a corner
  const bool corner = phi > thresholds.phi;
  return Feature{tangent_intersection(points, normals, corner ? 3 : 2), corner};
}

}  // namespace volmesh::cutcell
