#include "tangent_point.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <vector>
#include <cmath>

namespace volmesh::cutcell {

namespace {

Vec3 mass_point(std::span<const Vec3> points) {
  Vec3 mass = Vec3::Zero();
  for (const Vec3& s : points) mass += s;
  return mass / static_cast<double>(points.size());
}

// Normal equations A^T A x = A^T b per level with x = p - origin: the eigen-decomposition of
// the symmetric A^T A is the SVD of A, and its truncated inverse A's pseudo-inverse. Each
// level solves within the directions the earlier ones left free (the projector `free`
// removes the directions kept so far). `level` empty: one level.
Vec3 fit(std::span<const Vec3> points, std::span<const Vec3> normals, std::span<const std::uint8_t> level,
         const Vec3& origin, int max_rank, double relative_cutoff) {
  int levels = 1;
  for (std::uint8_t l : level) levels = std::max(levels, l + 1);
  std::vector<Eigen::Matrix3d> ata(levels, Eigen::Matrix3d::Zero());
  std::vector<Vec3> atb(levels, Vec3::Zero());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& n = normals[i];
    const int k = level.empty() ? 0 : level[i];
    ata[k] += n * n.transpose();
    atb[k] += n * n.dot(points[i] - origin);
  }
  Vec3 x = Vec3::Zero();
  Eigen::Matrix3d free = Eigen::Matrix3d::Identity();
  int rank = 0;
  for (int k = 0; k < levels && rank < max_rank; ++k) {
    // Eigenvalues ascending; they are the squared singular values of A. The cutoff is
    // relative to the set's own largest one, before the projection.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(free * ata[k] * free);
    const double largest =
        rank == 0 ? eigen.eigenvalues()[2]
                  : Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(ata[k], Eigen::EigenvaluesOnly).eigenvalues()[2];
    if (!(largest > 0.0)) continue;
    const Vec3 b = free * (atb[k] - ata[k] * x);
    const double cutoff = relative_cutoff * relative_cutoff * largest;
    for (int j = 2; j >= 0 && rank < max_rank; --j) {
      const double sigma = eigen.eigenvalues()[j];
      if (sigma <= cutoff) break;
      const Vec3 v = eigen.eigenvectors().col(j);
      x += v * (v.dot(b) / sigma);
      free -= v * v.transpose();
      ++rank;
    }
  }
  return origin + x;
}

}  // namespace

Vec3 tangent_intersection(std::span<const Vec3> points, std::span<const Vec3> normals,
                          int max_rank, double relative_cutoff) {
  return fit(points, normals, {}, mass_point(points), max_rank, relative_cutoff);
}

Vec3 tangent_intersection(std::span<const Vec3> points, std::span<const Vec3> normals,
                          const Vec3& origin, int max_rank, double relative_cutoff) {
  return fit(points, normals, {}, origin, max_rank, relative_cutoff);
}

Vec3 tangent_intersection_ranked(std::span<const Vec3> points, std::span<const Vec3> normals,
                                 std::span<const std::uint8_t> level, int max_rank, double relative_cutoff) {
  return fit(points, normals, level, mass_point(points), max_rank, relative_cutoff);
}

std::optional<Vec3> free_direction(std::span<const Vec3> normals, double relative_cutoff) {
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  for (const Vec3& n : normals) ata += n * n.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(ata);
  const double largest = eigen.eigenvalues()[2];
  if (!(largest > 0.0) || eigen.eigenvalues()[0] > relative_cutoff * relative_cutoff * largest ||
      eigen.eigenvalues()[1] <= relative_cutoff * relative_cutoff * largest)
    return std::nullopt;
  return Vec3(eigen.eigenvectors().col(0));
}

bool few_directions(std::span<const Vec3> normals, int max_planes, int min_points) {
  std::vector<Vec3> seen;
  std::vector<int> count;
  for (const Vec3& n : normals) {
    const auto same = [&n](const Vec3& m) { return n.dot(m) > 1.0 - kSameDirection; };
    const auto found = std::find_if(seen.begin(), seen.end(), same);
    if (found != seen.end()) {
      ++count[found - seen.begin()];
    } else {
      if (static_cast<int>(seen.size()) == max_planes) return false;
      seen.push_back(n);
      count.push_back(1);
    }
  }
  for (std::size_t k = 0; k < seen.size(); ++k)
    if (count[k] < min_points && !parallel_to_octree_faces(seen[k])) return false;
  return true;
}

std::optional<Feature> sharp_feature(std::span<const Vec3> points, std::span<const Vec3> normals,
                                     const FeatureThresholds& thresholds, std::span<const std::uint8_t> level) {
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
  return Feature{tangent_intersection_ranked(points, normals, level, corner ? 3 : 2), corner};
}

std::optional<TangentPlanes> planes_near_feature(std::span<const Vec3> s, std::span<const Vec3> n,
                                                 const Vec3& x, double reach, double shift,
                                                 const SurfaceNear& near) {
  std::vector<std::vector<std::size_t>> surfaces;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const auto same = std::find_if(surfaces.begin(), surfaces.end(),
                                   [&](const auto& g) { return n[g[0]].dot(n[i]) > kSameSurfaceCosine; });
    if (same == surfaces.end()) surfaces.push_back({i});
    else same->push_back(i);
  }
  if (surfaces.size() < 2) return std::nullopt;
  TangentPlanes out;
  for (const std::vector<std::size_t>& g : surfaces) {
    std::size_t nearest = g[0];
    Vec3 mass = Vec3::Zero();
    for (const std::size_t i : g) {
      if ((s[i] - x).squaredNorm() < (s[nearest] - x).squaredNorm()) nearest = i;
      mass += s[i] / static_cast<double>(g.size());
    }
    const Vec3& m = n[nearest];
    Vec3 along = (mass - x) - m.dot(mass - x) * m;
    if (along.norm() > 1e-9 * reach) along = shift * along.normalized();
    else along = Vec3::Zero();
    const auto found = near(x + along, reach * m);
    if (!found || !(found->second.dot(m) > kSameSurfaceCosine)) return std::nullopt;
    out.points.push_back(found->first);
    out.normals.push_back(found->second);
  }
  return out;
}

}  // namespace volmesh::cutcell
