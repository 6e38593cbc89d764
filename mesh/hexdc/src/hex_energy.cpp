#include "hex_energy.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "volmesh/hexdc/hex_quality.hpp"

namespace volmesh::hexdc_detail {
namespace {

// The unit cube's corners in VTK order.
constexpr std::array<std::array<int, 3>, 8> kUnitCube{
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
// kHexCornerTets' inner tets (4 and 9); the others are corner tets.
constexpr std::array<bool, 10> kInner{false, false, false, false, true,
                                      false, false, false, false, true};
// An inner tet's edges at its first corner are face diagonals, √2 each, in the unit cube, where
// 6 V = 2: its normalised volume times √2 is 1 there, as a corner's scaled Jacobian.
constexpr double kInnerScale = std::numbers::sqrt2;
constexpr double kTwoThirds = 2.0 / 3.0;
// A hex's soft-minimum terms: the ten tets, then its centre.
constexpr std::size_t kHexTerms = 11, kCentreTerm = 10;

Vec3 unit_corner(int c) {
  const auto& u = kUnitCube[static_cast<std::size_t>(c)];
  return {static_cast<double>(u[0]), static_cast<double>(u[1]), static_cast<double>(u[2])};
}

// R⁻¹ of each of the ten tets: J = E R⁻¹ is the identity in the unit cube.
const std::array<Eigen::Matrix3d, 10> kReferenceInverse = [] {
  std::array<Eigen::Matrix3d, 10> inverses;
  for (std::size_t t = 0; t < kHexCornerTets.size(); ++t) {
    const auto& [a, b, c, d] = kHexCornerTets[t];
    Eigen::Matrix3d r;
    r << unit_corner(b) - unit_corner(a), unit_corner(c) - unit_corner(a),
        unit_corner(d) - unit_corner(a);
    inverses[t] = r.inverse();
  }
  return inverses;
}();

Eigen::Matrix3d edges(const std::array<Vec3, 8>& p, const std::array<int, 4>& tet) {
  const auto& [a, b, c, d] = tet;
  Eigen::Matrix3d e;
  e << p[b] - p[a], p[c] - p[a], p[d] - p[a];
  return e;
}

// ∂ det / ∂ columns: the cofactor matrix.
Eigen::Matrix3d cofactor(const Eigen::Matrix3d& j) {
  Eigen::Matrix3d c;
  c << j.col(1).cross(j.col(2)), j.col(2).cross(j.col(0)), j.col(0).cross(j.col(1));
  return c;
}

// Adds the gradient in the edge matrix of a tet to its four corners.
void scatter(const Eigen::Matrix3d& d_edges, const std::array<int, 4>& tet, HexGradient& g) {
  const auto& [a, b, c, d] = tet;
  g[b] += d_edges.col(0);
  g[c] += d_edges.col(1);
  g[d] += d_edges.col(2);
  g[a] -= d_edges.col(0) + d_edges.col(1) + d_edges.col(2);
}

// χ and its derivative in D; χ written without cancellation for D < 0.
double chi(double d, double eps) {
  const double root = std::sqrt(eps * eps + d * d);
  return d > 0.0 ? 0.5 * (d + root) : 0.5 * eps * eps / (root - d);
}
double chi_derivative(double d, double eps) {
  const double root = std::sqrt(eps * eps + d * d);
  return root > 0.0 ? 0.5 + 0.5 * d / root : 0.5;
}

// A tet's scaled determinant and its gradient in the edge matrix.
double scaled_det(const Eigen::Matrix3d& e, double scale, Eigen::Matrix3d* d_edges) {
  const double a = e.col(0).norm(), b = e.col(1).norm(), c = e.col(2).norm();
  const double lengths = a * b * c;
  if (lengths == 0.0) {
    if (d_edges != nullptr) d_edges->setZero();
    return 0.0;
  }
  const Eigen::Matrix3d cof = cofactor(e);
  const double q = scale * e.col(0).dot(cof.col(0)) / lengths;
  if (d_edges != nullptr) {
    *d_edges = scale * cof / lengths;
    d_edges->col(0) -= q * e.col(0) / (a * a);
    d_edges->col(1) -= q * e.col(1) / (b * b);
    d_edges->col(2) -= q * e.col(2) / (c * c);
  }
  return q;
}

// The trilinear map's derivatives at the hex's centre, times 4: Verdict's principal axes, each
// the sum of the four corners on the axis's upper face less the four on its lower one. The
// sign of corner c in axis a.
constexpr std::array<std::array<int, 8>, 3> kAxisSign{{{-1, 1, 1, -1, -1, 1, 1, -1},
                                                       {-1, -1, 1, 1, -1, -1, 1, 1},
                                                       {-1, -1, -1, -1, 1, 1, 1, 1}}};

Eigen::Matrix3d principal_axes(const std::array<Vec3, 8>& p) {
  Eigen::Matrix3d axes = Eigen::Matrix3d::Zero();
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t c = 0; c < 8; ++c) axes.col(static_cast<Eigen::Index>(a)) += kAxisSign[a][c] * p[c];
  return axes;
}

// Adds the gradient in the principal axes to the eight corners.
void scatter_axes(const Eigen::Matrix3d& d_axes, HexGradient& g) {
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t c = 0; c < 8; ++c) g[c] += kAxisSign[a][c] * d_axes.col(static_cast<Eigen::Index>(a));
}

}  // namespace

double hex_barrier(const std::array<Vec3, 8>& p, double size, const Barrier& barrier,
                   HexGradient& gradient, double& min_det) {
  const double eps = barrier.epsilon, theta = barrier.theta;
  double energy = 0.0;
  for (std::size_t t = 0; t < kHexCornerTets.size(); ++t) {
    const Eigen::Matrix3d& r_inv = kReferenceInverse[t];
    const Eigen::Matrix3d j = edges(p, kHexCornerTets[t]) * r_inv / size;
    const Eigen::Matrix3d cof = cofactor(j);
    const double det = j.col(0).dot(cof.col(0));
    min_det = std::min(min_det, det);
    const double c = chi(det, eps), dc = chi_derivative(det, eps);
    const double trace = j.squaredNorm();
    const double c23 = std::cbrt(c * c);
    energy += (1.0 - theta) * trace / c23 + theta * (det * det + 1.0) / c;
    const double d_det = -(1.0 - theta) * kTwoThirds * trace / (c23 * c) * dc +
                         theta * (2.0 * det / c - (det * det + 1.0) * dc / (c * c));
    const Eigen::Matrix3d d_j = (1.0 - theta) * 2.0 / c23 * j + d_det * cof;
    scatter(d_j * r_inv.transpose() / size, kHexCornerTets[t], gradient);
  }
  return energy;
}

std::array<double, 10> hex_tet_qualities(const std::array<Vec3, 8>& p) {
  std::array<double, 10> q{};
  for (std::size_t t = 0; t < kHexCornerTets.size(); ++t)
    q[t] = scaled_det(edges(p, kHexCornerTets[t]), kInner[t] ? kInnerScale : 1.0, nullptr);
  return q;
}

double hex_centre_quality(const std::array<Vec3, 8>& p) {
  return scaled_det(principal_axes(p), 1.0, nullptr);
}

SoftminTerms hex_softmin_terms(const std::array<Vec3, 8>& p, double beta, HexGradient& gradient) {
  std::array<double, kHexTerms> q{};
  std::array<Eigen::Matrix3d, kHexTerms> d_edges;
  for (std::size_t t = 0; t < kHexCornerTets.size(); ++t)
    q[t] = scaled_det(edges(p, kHexCornerTets[t]), kInner[t] ? kInnerScale : 1.0, &d_edges[t]);
  q[kCentreTerm] = scaled_det(principal_axes(p), 1.0, &d_edges[kCentreTerm]);
  SoftminTerms terms;
  terms.least_tet = *std::min_element(q.begin(), q.begin() + kCentreTerm);
  terms.other = q[kCentreTerm];
  terms.least = std::min(terms.least_tet, terms.other);
  for (std::size_t t = 0; t < kHexTerms; ++t) {
    const double w = std::exp(-beta * (q[t] - terms.least));
    terms.sum += w;
    const Eigen::Matrix3d d = -beta * w * d_edges[t];
    if (t == kCentreTerm)
      scatter_axes(d, gradient);
    else
      scatter(d, kHexCornerTets[t], gradient);
  }
  return terms;
}

namespace {

struct QuadCorner {
  double sine = 0.0;
  Vec3 d_next = Vec3::Zero(), d_previous = Vec3::Zero();  // ∂ sine / ∂ the two edges
};

// The sine at a corner between the edges to its next and previous corners, about `normal`.
QuadCorner quad_corner(const Vec3& next, const Vec3& previous, const Vec3& normal) {
  QuadCorner c;
  const double a = next.norm(), b = previous.norm();
  if (a == 0.0 || b == 0.0) return c;
  c.sine = next.cross(previous).dot(normal) / (a * b);
  c.d_next = previous.cross(normal) / (a * b) - c.sine * next / (a * a);
  c.d_previous = normal.cross(next) / (a * b) - c.sine * previous / (b * b);
  return c;
}

Vec3 quad_normal(const std::array<Vec3, 4>& q) {
  return (q[2] - q[0]).cross(q[3] - q[1]).normalized();
}

}  // namespace

std::array<double, 4> quad_sines(const std::array<Vec3, 4>& q) {
  const Vec3 normal = quad_normal(q);
  std::array<double, 4> sines{};
  for (std::size_t k = 0; k < 4; ++k)
    sines[k] = quad_corner(q[(k + 1) % 4] - q[k], q[(k + 3) % 4] - q[k], normal).sine;
  return sines;
}

SoftminTerms quad_softmin_terms(const std::array<Vec3, 4>& q, double beta,
                                std::array<Vec3, 4>& gradient) {
  const Vec3 normal = quad_normal(q);
  std::array<QuadCorner, 4> corners;
  for (std::size_t k = 0; k < 4; ++k)
    corners[k] = quad_corner(q[(k + 1) % 4] - q[k], q[(k + 3) % 4] - q[k], normal);
  SoftminTerms terms;
  terms.least = std::min_element(corners.begin(), corners.end(), [](const auto& a, const auto& b) {
                  return a.sine < b.sine;
                })->sine;
  terms.least_tet = terms.other = terms.least;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t next = (k + 1) % 4, previous = (k + 3) % 4;
    const QuadCorner& c = corners[k];
    const double w = std::exp(-beta * (c.sine - terms.least));
    terms.sum += w;
    gradient[next] += -beta * w * c.d_next;
    gradient[previous] += -beta * w * c.d_previous;
    gradient[k] -= -beta * w * (c.d_next + c.d_previous);
  }
  return terms;
}

}  // namespace volmesh::hexdc_detail
