// Problems given as expressions, and the finite differences that check and differentiate them.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "problem_support.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/fem/expression.hpp"
#include "volmesh/fem/problems.hpp"

namespace volmesh::fem {

double finite_difference_laplacian(const ScalarFunction& u, const Vec3& p, double h) {
  const double centre = u(p);
  double sum = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 e = h * Vec3::Unit(axis);
    sum += -u(p + 2.0 * e) + 16.0 * u(p + e) - 30.0 * centre + 16.0 * u(p - e) - u(p - 2.0 * e);
  }
  return sum / (12.0 * h * h);
}

Vec3 finite_difference_gradient(const ScalarFunction& u, const Vec3& p, double h) {
  Vec3 g;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 e = h * Vec3::Unit(axis);
    g[axis] = (-u(p + 2.0 * e) + 8.0 * u(p + e) - 8.0 * u(p - e) + u(p - 2.0 * e)) / (12.0 * h);
  }
  return g;
}

namespace {

constexpr int kSamples = 64;
constexpr double kMismatch = 3e-4;

// The i-th point of the Halton sequence (bases 2, 3, 5) in the unit cube: deterministic and
// spread evenly without a random generator.
Vec3 halton(int i) {
  Vec3 p;
  const int bases[3] = {2, 3, 5};
  for (int axis = 0; axis < 3; ++axis) {
    double f = 1.0, r = 0.0;
    for (int n = i + 1; n > 0; n /= bases[axis]) {
      f /= bases[axis];
      r += f * (n % bases[axis]);
    }
    p[axis] = r;
  }
  return p;
}

std::vector<Vec3> points_inside(const Domain& domain) {
  const Box3 box = domain.bounds();
  std::vector<Vec3> points;
  for (int i = 0; i < 100 * kSamples && static_cast<int>(points.size()) < kSamples; ++i) {
    const Vec3 p = box.lo + halton(i).cwiseProduct(box.size());
    if (domain.region(p) != 0) points.push_back(p);
  }
  return points;
}

std::string format_point(const Vec3& p) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// Compares f with −kΔu at points inside the domain; empty when they agree.
std::string source_mismatch(const ScalarFunction& exact, const ScalarFunction& source, double k,
                            double h, const Domain& domain) {
  struct Sample {
    Vec3 point;
    double minus_k_laplacian, source;
  };
  std::vector<Sample> samples;
  double scale = 0.0, largest_u = 0.0;
  for (const Vec3& p : points_inside(domain)) {
    const Sample s{p, -k * finite_difference_laplacian(exact, p, h), source(p)};
    samples.push_back(s);
    for (double v : {s.source, s.minus_k_laplacian})
      if (std::isfinite(v)) scale = std::max(scale, std::abs(v));
    if (std::isfinite(exact(p))) largest_u = std::max(largest_u, std::abs(exact(p)));
  }
  // Rounding in the difference quotient, for a source that is zero everywhere.
  const double rounding = 100.0 * std::numeric_limits<double>::epsilon() * k * largest_u / (h * h);
  int bad = 0;
  const Sample* first = nullptr;
  for (const Sample& s : samples) {
    const double difference = std::abs(s.minus_k_laplacian - s.source);
    if (!(difference <= kMismatch * scale + rounding)) {
      ++bad;
      if (!first) first = &s;
    }
  }
  if (!first) return {};
  std::ostringstream msg;
  msg.precision(8);
  msg << "--source does not match -k*laplacian(--exact) at " << bad << " of " << samples.size()
      << " points inside the domain, e.g. at " << format_point(first->point)
      << ": -k*laplacian(u) = " << first->minus_k_laplacian << ", f = " << first->source
      << "; the errors will not converge";
  return msg.str();
}

}  // namespace

UserPoissonProblem user_poisson_problem(const std::string& exact_text,
                                        const std::string& source_text, double k,
                                        const Domain& domain,
                                        const std::vector<std::string>& tags) {
  if (exact_text.empty() && source_text.empty())
    throw InputError("user problem: give --exact, --source or both");
  if (!(k > 0.0) || !std::isfinite(k))
    throw InputError("user problem: the conductivity k must be positive and finite, got " +
                     std::to_string(k));
  // Steps well above rounding (relative 1e-16 · |u| / h² for the Laplacian) and well below the
  // size of any feature a mesh of the domain resolves.
  const double h = 1e-3 * std::min(1.0, domain.bounds().size().maxCoeff());

  UserPoissonProblem user;
  PoissonProblem& p = user.problem;
  p.conductivity = same_conductivity(domain, k);
  p.to_true_boundary = true_boundary_map(domain);
  if (!source_text.empty()) p.source = parse_expression(source_text, "--source");
  if (exact_text.empty()) {
    p.boundary = on_every_tag(
        tags, {ScalarBoundaryCondition::Kind::dirichlet, [](const Vec3&) { return 0.0; }});
    return user;
  }
  const ScalarFunction exact = parse_expression(exact_text, "--exact");
  p.exact = exact;
  p.exact_gradient = [exact, h](const Vec3& x) { return finite_difference_gradient(exact, x, h); };
  p.boundary = on_every_tag(tags, {ScalarBoundaryCondition::Kind::dirichlet, exact});
  if (p.source) {
    user.warning = source_mismatch(exact, p.source, k, h, domain);
  } else {
    p.source = [exact, k, h](const Vec3& x) {
      return -k * finite_difference_laplacian(exact, x, h);
    };
  }
  return user;
}

}  // namespace volmesh::fem
