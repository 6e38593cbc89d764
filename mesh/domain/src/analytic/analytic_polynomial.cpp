// Root isolation by derivative splitting, then safeguarded Newton-bisection per root.
#include "analytic_polynomial.hpp"

#include <algorithm>
#include <cmath>

namespace volmesh::analytic {
namespace {

double eval(const double* c, int degree, double x) {
  double v = c[degree];
  for (int k = degree - 1; k >= 0; --k) v = v * x + c[k];
  return v;
}

int sign(double v) { return (v > 0.0) - (v < 0.0); }

// The root inside [x0, x1], where the polynomial is monotone and changes sign (f0 = f(x0)):
// Newton steps while they stay in the bracket and shrink fast enough, else bisection.
double refine(const double* c, const double* dc, int degree, double x0, double x1,
              double f0) {
  double neg = f0 < 0.0 ? x0 : x1, pos = f0 < 0.0 ? x1 : x0;
  double x = 0.5 * (x0 + x1);
  double step = x1 - x0, step_before = step;
  for (int it = 0; it < 200; ++it) {
    const double f = eval(c, degree, x);
    if (f == 0.0) return x;
    (f < 0.0 ? neg : pos) = x;
    const double lo = std::min(neg, pos), hi = std::max(neg, pos);
    const double df = eval(dc, degree - 1, x);
    const double newton = x - f / df;
    step_before = step;
    if (newton > lo && newton < hi && std::abs(2.0 * f) < std::abs(step_before * df)) {
      if (newton == x) return x;
      step = newton - x;
      x = newton;
    } else {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) return x;  // the bracket is at machine resolution
      step = mid - x;
      x = mid;
    }
  }
  return x;
}

}  // namespace

PolynomialRoots polynomial_roots(const double* c, int degree, double lo, double hi) {
  PolynomialRoots out;
  if (degree == 0) {
    out.start_sign = sign(c[0]);
    return out;
  }
  std::array<double, kMaxDegree> dc;
  for (int k = 0; k < degree; ++k) dc[k] = (k + 1) * c[k + 1];

  // Break points: the ends and the derivative's roots between them.
  std::array<double, kMaxDegree + 1> x, f;
  int m = 0;
  x[m++] = lo;
  if (degree >= 2) {
    const PolynomialRoots critical = polynomial_roots(dc.data(), degree - 1, lo, hi);
    for (int k = 0; k < critical.count; ++k)
      if (critical.roots[k] > x[m - 1] && critical.roots[k] < hi) x[m++] = critical.roots[k];
  }
  x[m++] = hi;
  for (int i = 0; i < m; ++i) f[i] = eval(c, degree, x[i]);

  // Walk the pieces; a root's sign_after is the next nonzero sign seen.
  int pending = 0, last_sign = 0;
  const auto add_root = [&](double r) {
    if ((out.count > 0 && out.roots[out.count - 1] == r) || out.count == kMaxDegree) return;
    out.roots[out.count] = r;
    out.sign_after[out.count++] = 0;
    ++pending;
  };
  const auto add_sign = [&](int s) {
    if (out.start_sign == 0) out.start_sign = s;
    for (int k = out.count - pending; k < out.count; ++k) out.sign_after[k] = s;
    pending = 0;
    last_sign = s;
  };
  const auto visit = [&](int i) { f[i] == 0.0 ? add_root(x[i]) : add_sign(sign(f[i])); };
  visit(0);
  for (int i = 0; i + 1 < m; ++i) {
    if (f[i] != 0.0 && f[i + 1] != 0.0 && (f[i] < 0.0) != (f[i + 1] < 0.0))
      add_root(refine(c, dc.data(), degree, x[i], x[i + 1], f[i]));
    visit(i + 1);
  }
  for (int k = out.count - pending; k < out.count; ++k) out.sign_after[k] = last_sign;
  return out;
}

}  // namespace volmesh::analytic
