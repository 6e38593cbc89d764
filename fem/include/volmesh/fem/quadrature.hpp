#pragma once
// Quadrature rules on the reference tetrahedron, triangle and interval. Simplex rules are in
// barycentric coordinates with weights summing to 1 (multiply by the element's volume or
// area); every weight is positive.
#include <array>
#include <span>

namespace volmesh::fem {

struct TetQuadraturePoint {
  std::array<double, 4> barycentric;
  double weight;
};

struct TriangleQuadraturePoint {
  std::array<double, 3> barycentric;
  double weight;
};

struct GaussPoint {
  double x;       // in [-1, 1]
  double weight;  // the weights of a rule sum to 2
};

// The smallest stored rule exact for polynomials of the given degree (at most 5):
// degree 1 → 1 point (centroid), 2 → 4 points, 3 to 5 → 14 points (Walkington's degree-5 rule).
std::span<const TetQuadraturePoint> tet_rule(int degree);

// Degree 1 → 1 point, 2 → 3 points, 3 to 5 → 7 points (Dunavant's degree-5 rule).
std::span<const TriangleQuadraturePoint> triangle_rule(int degree);

// Gauss–Legendre with n = 1…4 points, exact to degree 2n − 1.
std::span<const GaussPoint> gauss_legendre(int n);

}  // namespace volmesh::fem
