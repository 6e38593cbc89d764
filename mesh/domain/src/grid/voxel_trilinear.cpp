#include "voxel_trilinear.hpp"

#include <algorithm>
#include <cmath>

namespace volmesh::voxel {

namespace {

// Polynomials in s as coefficient arrays; a lerp between p and q with the linear weight w:
// p + w (q - p), the degree growing by one.
template <std::size_t N>
std::array<double, N + 1> lerp(const std::array<double, N>& p, const std::array<double, N>& q,
                               const std::array<double, 2>& w) {
  std::array<double, N + 1> r{};
  for (std::size_t i = 0; i < N; ++i) {
    r[i] += p[i] + w[0] * (q[i] - p[i]);
    r[i + 1] += w[1] * (q[i] - p[i]);
  }
  return r;
}

}  // namespace

Cubic cubic_along(const std::array<double, 8>& c, const Vec3& f0, const Vec3& df) {
  const std::array<double, 2> wx{f0.x(), df.x()}, wy{f0.y(), df.y()}, wz{f0.z(), df.z()};
  std::array<std::array<double, 2>, 4> along_x;  // one per (y, z) corner pair
  for (int e = 0; e < 4; ++e) along_x[e] = lerp<1>({c[2 * e]}, {c[2 * e + 1]}, wx);
  const auto y0 = lerp<2>(along_x[0], along_x[1], wy), y1 = lerp<2>(along_x[2], along_x[3], wy);
  return Cubic{lerp<3>(y0, y1, wz)};
}

int critical_points(const Cubic& g, double len, std::array<double, 2>& out) {
  // g'(s) = a s^2 + b s + c, solved without cancellation.
  const double a = 3.0 * g.c[3], b = 2.0 * g.c[2], c = g.c[1];
  std::array<double, 2> roots{};
  int n = 0;
  if (a == 0.0) {
    if (b != 0.0) roots[n++] = -c / b;
  } else {
    const double disc = b * b - 4.0 * a * c;
    if (disc >= 0.0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      roots[n++] = q / a;
      if (q != 0.0) roots[n++] = c / q;
    }
  }
  int kept = 0;
  for (int i = 0; i < n; ++i)
    if (roots[i] > 0.0 && roots[i] < len) out[kept++] = roots[i];
  if (kept == 2) {
    if (out[0] > out[1]) std::swap(out[0], out[1]);
    if (out[0] == out[1]) kept = 1;
  }
  return kept;
}

double bracketed_root(const Cubic& g, double lo, double hi, bool rising) {
  double x = lo + 0.5 * (hi - lo);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double v = g(x);
    if (v == 0.0) return x;
    ((v < 0.0) == rising ? lo : hi) = x;
    double next = x - v / g.derivative(x);
    if (!(next > lo && next < hi)) next = lo + 0.5 * (hi - lo);  // Newton left the bracket
    if (next <= lo || next >= hi || next == x) return x;         // no double left in between
    x = next;
  }
  return x;
}

}  // namespace volmesh::voxel
