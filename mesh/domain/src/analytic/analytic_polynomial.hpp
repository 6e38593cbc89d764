#pragma once
// Real roots of a polynomial of degree <= 4 on an interval. The interval is split at the
// roots of the derivative (found the same way, recursively) into pieces where the
// polynomial is monotone, so each piece holds at most one root and two close roots are
// never missed as long as the sign between them can be evaluated.
#include <array>

namespace volmesh::analytic {

inline constexpr int kMaxDegree = 4;

struct PolynomialRoots {
  int start_sign = 0;  // sign of the polynomial at the start of the interval (before any root)
  int count = 0;
  std::array<double, kMaxDegree> roots;    // sorted
  std::array<int, kMaxDegree> sign_after;  // equal to the sign before for a touching root
};

// Roots of c[0] + c[1] x + ... + c[degree] x^degree in [lo, hi] (c[degree] != 0), each
// refined by safeguarded Newton-bisection to machine precision.
PolynomialRoots polynomial_roots(const double* c, int degree, double lo, double hi);

}  // namespace volmesh::analytic
