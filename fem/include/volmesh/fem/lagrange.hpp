#pragma once
// Lagrange shape functions: P1 and P2 on affine tetrahedra and triangles, Q1 (trilinear) on
// hexahedra and bilinear on quadrilaterals. Inline: they run once per quadrature point.
#include <Eigen/Core>
#include <array>
#include <span>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/types.hpp"

namespace volmesh::fem {

// An affine tetrahedron (a, b, c, d): its signed volume (positive when det(b-a, c-a, d-a) > 0,
// as core's tet_volume) and the gradients of its four barycentric coordinates. The gradients
// are meaningless when the volume is zero.
struct TetAffine {
  double volume;
  std::array<Vec3, 4> gradient;
};

inline TetAffine tet_affine(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 e1 = b - a, e2 = c - a, e3 = d - a;
  // Rows of the inverse Jacobian [e1 e2 e3]⁻¹ by cross products.
  const Vec3 n1 = e2.cross(e3), n2 = e3.cross(e1), n3 = e1.cross(e2);
  const double det = e1.dot(n1);
  TetAffine t;
  t.volume = det / 6.0;
  const double inv = det != 0.0 ? 1.0 / det : 0.0;
  t.gradient[1] = n1 * inv;
  t.gradient[2] = n2 * inv;
  t.gradient[3] = n3 * inv;
  t.gradient[0] = -(t.gradient[1] + t.gradient[2] + t.gradient[3]);
  return t;
}

// P2 local nodes: the 4 corners, then the 6 edge midpoints in core's kTetEdges order, VTK's
// quadratic-tet order.

inline void p2_tet_values(const std::array<double, 4>& l, std::span<double, 10> n) {
  for (int i = 0; i < 4; ++i) n[i] = l[i] * (2.0 * l[i] - 1.0);
  for (int e = 0; e < 6; ++e) n[4 + e] = 4.0 * l[kTetEdges[e][0]] * l[kTetEdges[e][1]];
}

inline void p2_tet_gradients(const std::array<double, 4>& l, const std::array<Vec3, 4>& dl,
                             std::span<Vec3, 10> g) {
  for (int i = 0; i < 4; ++i) g[i] = (4.0 * l[i] - 1.0) * dl[i];
  for (int e = 0; e < 6; ++e) {
    const int i = kTetEdges[e][0], j = kTetEdges[e][1];
    g[4 + e] = 4.0 * (l[i] * dl[j] + l[j] * dl[i]);
  }
}

// P2 on a triangle: the 3 corners, then the midpoints of edges (0,1), (1,2), (2,0) — the
// edges of a face loop in loop order.
inline constexpr std::array<std::array<int, 2>, 3> kTriangleEdges{{{0, 1}, {1, 2}, {2, 0}}};

inline void p2_triangle_values(const std::array<double, 3>& l, std::span<double, 6> n) {
  for (int i = 0; i < 3; ++i) n[i] = l[i] * (2.0 * l[i] - 1.0);
  for (int e = 0; e < 3; ++e) n[3 + e] = 4.0 * l[kTriangleEdges[e][0]] * l[kTriangleEdges[e][1]];
}

// Q1 on the reference cube [-1, 1]³ with corners in VTK hex order.
inline constexpr std::array<std::array<double, 3>, 8> kHexCorners{{{-1, -1, -1},
                                                                   {1, -1, -1},
                                                                   {1, 1, -1},
                                                                   {-1, 1, -1},
                                                                   {-1, -1, 1},
                                                                   {1, -1, 1},
                                                                   {1, 1, 1},
                                                                   {-1, 1, 1}}};

inline void q1_hex_values(const Vec3& xi, std::span<double, 8> n) {
  for (int a = 0; a < 8; ++a) {
    const auto& s = kHexCorners[a];
    n[a] = 0.125 * (1.0 + s[0] * xi[0]) * (1.0 + s[1] * xi[1]) * (1.0 + s[2] * xi[2]);
  }
}

// Gradients with respect to the reference coordinates ξ.
inline void q1_hex_reference_gradients(const Vec3& xi, std::span<Vec3, 8> g) {
  for (int a = 0; a < 8; ++a) {
    const auto& s = kHexCorners[a];
    const double fx = 1.0 + s[0] * xi[0], fy = 1.0 + s[1] * xi[1], fz = 1.0 + s[2] * xi[2];
    g[a] = 0.125 * Vec3(s[0] * fy * fz, fx * s[1] * fz, fx * fy * s[2]);
  }
}

// Bilinear shape functions on [-1, 1]² with corners (-1,-1), (1,-1), (1,1), (-1,1): a face
// loop's vertices in loop order.
inline constexpr std::array<std::array<double, 2>, 4> kQuadCorners{
    {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};

inline void q1_quad_values(double xi, double eta, std::span<double, 4> n) {
  for (int a = 0; a < 4; ++a)
    n[a] = 0.25 * (1.0 + kQuadCorners[a][0] * xi) * (1.0 + kQuadCorners[a][1] * eta);
}

inline void q1_quad_reference_gradients(double xi, double eta, std::span<Eigen::Vector2d, 4> g) {
  for (int a = 0; a < 4; ++a) {
    const double sx = kQuadCorners[a][0], sy = kQuadCorners[a][1];
    g[a] = 0.25 * Eigen::Vector2d(sx * (1.0 + sy * eta), (1.0 + sx * xi) * sy);
  }
}

}  // namespace volmesh::fem
