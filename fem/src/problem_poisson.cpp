// The named Poisson problems (problems.hpp describes them).
#include <cmath>
#include <limits>

#include "problem_support.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/fem/problems.hpp"

namespace volmesh::fem {

std::map<std::string, ScalarBoundaryCondition> on_every_tag(const std::vector<std::string>& tags,
                                                            const ScalarBoundaryCondition& bc) {
  std::map<std::string, ScalarBoundaryCondition> boundary;
  for (const std::string& tag : tags) boundary[tag] = bc;
  return boundary;
}

std::map<Index, double> same_conductivity(const Domain& domain, double k) {
  std::map<Index, double> conductivity;
  for (Index r : domain.regions()) conductivity[r] = k;
  return conductivity;
}

ScalarFunction boundary_flux(const Domain& domain, double k, VectorFunction gradient) {
  const Domain* d = &domain;
  return [d, k, gradient = std::move(gradient)](const Vec3& q) {
    return k * gradient(q).dot(d->normal(q));
  };
}

namespace {

// Shifted so that no factor vanishes on a coordinate plane: boundary data are never
// trivially zero on the faces of the unit cube or at the centre of a ball.
// The error integrals ask for u and ∇u at the same points, one after the other: the three
// sines and cosines of the last point are kept per thread, so that the pair costs three
// sincos calls (each one evaluation for both, the same values as sin and cos) instead of
// three sines and three sines and cosines.
struct SineFactors {
  Vec3 at = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  double sx = 0.0, sy = 0.0, sz = 0.0, cx = 0.0, cy = 0.0, cz = 0.0;
};

const SineFactors& sine_factors(const Vec3& p) {
  thread_local SineFactors f;
  if (p != f.at) {
    f.at = p;
    __builtin_sincos(p.x() + 0.3, &f.sx, &f.cx);
    __builtin_sincos(2.0 * p.y() + 0.1, &f.sy, &f.cy);
    __builtin_sincos(3.0 * p.z() + 0.7, &f.sz, &f.cz);
  }
  return f;
}

double sine(const Vec3& p) {
  const SineFactors& f = sine_factors(p);
  return f.sx * f.sy * f.sz;
}

Vec3 sine_gradient(const Vec3& p) {
  const SineFactors& f = sine_factors(p);
  return {f.cx * f.sy * f.sz, 2.0 * f.sx * f.cy * f.sz, 3.0 * f.sx * f.sy * f.cz};
}

PoissonProblem sine_problem(const Domain& domain, const std::vector<std::string>& tags) {
  PoissonProblem p;
  p.conductivity = same_conductivity(domain, 1.0);
  p.source = [](const Vec3& x) { return 14.0 * sine(x); };
  p.boundary = on_every_tag(tags, {ScalarBoundaryCondition::Kind::dirichlet, sine});
  p.to_true_boundary = true_boundary_map(domain);
  p.exact = sine;
  p.exact_gradient = sine_gradient;
  return p;
}

PoissonProblem sine_neumann_problem(const Domain& domain, const std::vector<std::string>& tags) {
  if (tags.size() < 2)
    throw InputError("problem sine-neumann: needs two boundary tags or more (u on the first, "
                     "the flux on the others); the mesh has " +
                     std::to_string(tags.size()));
  PoissonProblem p = sine_problem(domain, tags);
  const ScalarBoundaryCondition flux{ScalarBoundaryCondition::Kind::neumann,
                                     boundary_flux(domain, 1.0, sine_gradient)};
  for (std::size_t i = 1; i < tags.size(); ++i) p.boundary[tags[i]] = flux;
  return p;
}

PoissonProblem patch_linear_problem(const Domain& domain, const std::vector<std::string>& tags) {
  const Vec3 gradient(2.0, -1.0, 3.0);
  const auto linear = [gradient](const Vec3& x) { return 1.0 + gradient.dot(x); };
  PoissonProblem p;
  p.conductivity = same_conductivity(domain, 2.5);
  p.boundary = on_every_tag(tags, {ScalarBoundaryCondition::Kind::dirichlet, linear});
  p.to_true_boundary = true_boundary_map(domain);
  p.exact = linear;
  p.exact_gradient = [gradient](const Vec3&) { return gradient; };
  return p;
}

PoissonProblem multi_material_problem(const Domain& domain,
                                      const std::vector<std::string>& tags) {
  PoissonProblem p;
  for (Index r : domain.regions()) p.conductivity[r] = static_cast<double>(r);
  p.source = [](const Vec3&) { return 1.0; };
  p.boundary = on_every_tag(
      tags, {ScalarBoundaryCondition::Kind::dirichlet, [](const Vec3&) { return 0.0; }});
  p.to_true_boundary = true_boundary_map(domain);
  return p;
}

}  // namespace

PoissonProblem make_poisson_problem(const std::string& name, const Domain& domain,
                                    const std::vector<std::string>& tags) {
  using Maker = PoissonProblem (*)(const Domain&, const std::vector<std::string>&);
  static const std::map<std::string, Maker> makers{{"sine", sine_problem},
                                                   {"sine-neumann", sine_neumann_problem},
                                                   {"patch-linear", patch_linear_problem},
                                                   {"multi-material", multi_material_problem}};
  const auto it = makers.find(name);
  if (it == makers.end()) {
    problem_kind(name);  // throws for an unknown name, listing the valid ones
    throw InputError("problem " + name + ": an elasticity problem, not a Poisson one");
  }
  return it->second(domain, tags);
}

}  // namespace volmesh::fem
