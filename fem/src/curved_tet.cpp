#include "curved_tet.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/LU>
#include <algorithm>
#include <limits>

#include "volmesh/fem/lagrange.hpp"

namespace volmesh::fem::detail {
namespace {

// Gradients of the barycentric coordinates λ0 = 1 − λ1 − λ2 − λ3, λ1, λ2, λ3 with respect to
// the reference coordinates (λ1, λ2, λ3).
const std::array<Vec3, 4> kTetReference{Vec3(-1, -1, -1), Vec3(1, 0, 0), Vec3(0, 1, 0),
                                        Vec3(0, 0, 1)};
// The reference tet's volume: a rule's weights sum to 1.
constexpr double kTetReferenceVolume = 1.0 / 6.0;
constexpr double kTriangleReferenceArea = 0.5;

// A mapped midpoint closer than this (relative to the edge's length) to the straight one
// leaves the edge straight: a flat side, up to the rounding of the boundary map.
constexpr double kFlat = 1e-8;

}  // namespace

double curved_tet_point(const std::array<Vec3, 10>& nodes, const std::array<double, 4>& l,
                        Vec3& x, std::span<double, 10> value, std::span<Vec3, 10> gradient) {
  p2_tet_values(l, value);
  p2_tet_gradients(l, kTetReference, gradient);
  x.setZero();
  Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();  // column j: ∂x/∂λ_j
  for (int k = 0; k < 10; ++k) {
    x += value[k] * nodes[k];
    jacobian += nodes[k] * gradient[k].transpose();
  }
  const double det = jacobian.determinant();
  if (det > 0.0) {
    const Eigen::Matrix3d inverse_transpose = jacobian.inverse().transpose();
    for (Vec3& g : gradient) g = inverse_transpose * g;
  }
  return kTetReferenceVolume * det;
}

double curved_triangle_point(const std::array<Vec3, 6>& nodes, const std::array<double, 3>& l,
                             Vec3& x) {
  static const std::array<Eigen::Vector2d, 3> kReference{
      Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)};
  std::array<double, 6> value;
  p2_triangle_values(l, value);
  std::array<Eigen::Vector2d, 6> gradient;
  for (int i = 0; i < 3; ++i) gradient[i] = (4.0 * l[i] - 1.0) * kReference[i];
  for (int e = 0; e < 3; ++e) {
    const int i = kTriangleEdges[e][0], j = kTriangleEdges[e][1];
    gradient[3 + e] = 4.0 * (l[i] * kReference[j] + l[j] * kReference[i]);
  }
  x.setZero();
  Vec3 ds = Vec3::Zero(), dt = Vec3::Zero();
  for (int k = 0; k < 6; ++k) {
    x += value[k] * nodes[k];
    ds += gradient[k][0] * nodes[k];
    dt += gradient[k][1] * nodes[k];
  }
  return kTriangleReferenceArea * ds.cross(dt).norm();
}

std::vector<Vec3> boundary_edge_nodes(const PolyMesh& mesh,
                                      std::span<const std::array<Index, 2>> edges,
                                      const PointMap& to_true_boundary, std::vector<char>& moved) {
  std::vector<Vec3> out(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e)
    out[e] = 0.5 * (mesh.points[edges[e][0]] + mesh.points[edges[e][1]]);
  moved.assign(edges.size(), 0);
  if (!to_true_boundary) return out;

  // The boundary faces' edges and points.
  std::vector<std::size_t> candidates;
  std::vector<Index> points;
  std::vector<char> is_candidate(edges.size(), 0), is_point(mesh.num_points(), 0);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (!mesh.is_boundary(f)) continue;
    const auto loop = mesh.face(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Index a = loop[i], b = loop[(i + 1) % loop.size()];
      const std::array<Index, 2> key{std::min(a, b), std::max(a, b)};
      const auto it = std::lower_bound(edges.begin(), edges.end(), key);
      if (it == edges.end() || *it != key) continue;
      const std::size_t e = static_cast<std::size_t>(it - edges.begin());
      if (!is_candidate[e]) candidates.push_back(e);
      if (!is_point[a]) points.push_back(a);
      is_candidate[e] = is_point[a] = 1;
    }
  }
  std::vector<double> off_boundary(mesh.num_points(), std::numeric_limits<double>::infinity());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size()),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k != r.end(); ++k) {
                        const Vec3& p = mesh.points[points[k]];
                        off_boundary[points[k]] = (to_true_boundary(p) - p).norm();
                      }
                    });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size()),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k != r.end(); ++k) {
                        const std::size_t e = candidates[k];
                        const Index a = edges[e][0], b = edges[e][1];
                        const double length = (mesh.points[a] - mesh.points[b]).norm();
                        if (off_boundary[a] > kOnBoundary * length ||
                            off_boundary[b] > kOnBoundary * length)
                          continue;
                        const Vec3 q = to_true_boundary(out[e]);
                        if ((q - out[e]).norm() <= kFlat * length) continue;
                        out[e] = q;
                        moved[e] = 1;
                      }
                    });
  return out;
}

}  // namespace volmesh::fem::detail
