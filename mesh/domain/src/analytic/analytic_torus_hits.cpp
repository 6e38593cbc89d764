// Line and torus: the quartic (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2) = 0 along the line,
// written in the arc length u from the line's point nearest to the centre, so that its
// coefficients stay of the size of the torus whatever the segment.
#include "analytic_polynomial.hpp"
#include "analytic_shapes.hpp"

namespace volmesh::analytic {

LineHits line_hits(const Torus& tor, const Vec3& a, const Vec3& d) {
  const double len = d.norm();
  const Vec3 e = d / len;
  const double t_c = -a.dot(e) / len;
  const Vec3 c = a + t_c * d;  // p(u) = c + u e, t = t_c + u / len

  const double R2 = tor.major * tor.major;
  const double alpha = e.squaredNorm(), beta = 2.0 * c.dot(e);
  const double gamma = c.squaredNorm() + R2 - tor.minor * tor.minor;
  const double s2 = e.x() * e.x() + e.y() * e.y(), s1 = 2.0 * (c.x() * e.x() + c.y() * e.y()),
               s0 = c.x() * c.x() + c.y() * c.y();
  const double coeffs[5] = {gamma * gamma - 4.0 * R2 * s0, 2.0 * beta * gamma - 4.0 * R2 * s1,
                            beta * beta + 2.0 * alpha * gamma - 4.0 * R2 * s2,
                            2.0 * alpha * beta, alpha * alpha};

  const double u_lo = (-kSearchMargin - t_c) * len, u_hi = (1.0 + kSearchMargin - t_c) * len;
  const PolynomialRoots r = polynomial_roots(coeffs, 4, u_lo, u_hi);
  LineHits h;
  h.start = r.start_sign < 0 ? Side::in : Side::out;
  for (int k = 0; k < r.count; ++k) {
    h.add(t_c + r.roots[k] / len, r.sign_after[k] < 0 ? Side::in : Side::out,
          gradient(tor, c + r.roots[k] * e));
  }
  return h;
}

}  // namespace volmesh::analytic
