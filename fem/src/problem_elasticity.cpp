// The named elasticity problems (problems.hpp describes them).
#include <algorithm>

#include "volmesh/core/errors.hpp"
#include "volmesh/fem/problems.hpp"

namespace volmesh::fem {
namespace {

std::map<Index, IsotropicMaterial> same_material(const Domain& domain, IsotropicMaterial m) {
  std::map<Index, IsotropicMaterial> material;
  for (Index r : domain.regions()) material[r] = m;
  return material;
}

// u = (A + B/r³) x: the radial field A r + B/r² of the Lamé solution.
struct Lame {
  static constexpr double inner = 0.5, outer = 1.0, pressure = 1.0;
  IsotropicMaterial material;
  double a = 0.0, b = 0.0;

  explicit Lame(IsotropicMaterial m) : material(m) {
    const double e = m.young, nu = m.poisson;
    const double lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu = e / (2.0 * (1.0 + nu));
    const double ri3 = inner * inner * inner, ro3 = outer * outer * outer;
    a = pressure * ri3 / ((3.0 * lambda + 2.0 * mu) * (ro3 - ri3));
    b = pressure * ri3 * ro3 / (4.0 * mu * (ro3 - ri3));
  }
  Vec3 displacement(const Vec3& x) const {
    const double r = x.norm();
    return (a + b / (r * r * r)) * x;
  }
  Eigen::Matrix3d gradient(const Vec3& x) const {
    const double r2 = x.squaredNorm(), r = std::sqrt(r2);
    const double f = a + b / (r2 * r);
    return f * Eigen::Matrix3d::Identity() - (3.0 * b / (r2 * r2 * r)) * x * x.transpose();
  }
};

ElasticityProblem lame_problem(const Domain& domain, const std::vector<std::string>& tags) {
  const bool served = std::count(tags.begin(), tags.end(), "inner") == 1 &&
                      std::count(tags.begin(), tags.end(), "outer") == 1 && tags.size() == 2;
  if (!served) {
    std::string have;
    for (const std::string& t : tags) have += (have.empty() ? "" : ", ") + t;
    throw InputError("problem lame: needs exactly the boundary tags inner and outer "
                     "(builtin:thick-sphere); the mesh has: " +
                     (have.empty() ? std::string("none") : have));
  }
  const Lame lame(IsotropicMaterial{});
  ElasticityProblem p;
  p.material = same_material(domain, lame.material);
  p.to_true_boundary = true_boundary_map(domain);
  const Domain* d = &domain;
  p.boundary["inner"] = {VectorBoundaryCondition::Kind::traction,
                         [d](const Vec3& q) -> Vec3 { return -Lame::pressure * d->normal(q); }};
  p.boundary["outer"] = {VectorBoundaryCondition::Kind::displacement,
                         [lame](const Vec3& q) { return lame.displacement(q); }};
  p.exact = [lame](const Vec3& x) { return lame.displacement(x); };
  p.exact_gradient = [lame](const Vec3& x) { return lame.gradient(x); };
  return p;
}

ElasticityProblem elastic_patch_problem(const Domain& domain,
                                        const std::vector<std::string>& tags) {
  const Vec3 shift(0.1, -0.2, 0.05);
  Eigen::Matrix3d gradient;
  gradient << 0.2, -0.1, 0.3,  //
      0.1, 0.4, -0.2,          //
      -0.3, 0.1, 0.2;
  const VectorFunction linear = [shift, gradient](const Vec3& x) -> Vec3 {
    return shift + gradient * x;
  };
  ElasticityProblem p;
  p.material = same_material(domain, IsotropicMaterial{});
  for (const std::string& tag : tags)
    p.boundary[tag] = {VectorBoundaryCondition::Kind::displacement, linear};
  p.to_true_boundary = true_boundary_map(domain);
  p.exact = linear;
  p.exact_gradient = [gradient](const Vec3&) { return gradient; };
  return p;
}

}  // namespace

ElasticityProblem make_elasticity_problem(const std::string& name, const Domain& domain,
                                          const std::vector<std::string>& tags) {
  using Maker = ElasticityProblem (*)(const Domain&, const std::vector<std::string>&);
  static const std::map<std::string, Maker> makers{{"lame", lame_problem},
                                                   {"elastic-patch", elastic_patch_problem}};
  const auto it = makers.find(name);
  if (it == makers.end()) {
    problem_kind(name);  // throws for an unknown name, listing the valid ones
    throw InputError("problem " + name + ": a Poisson problem, not an elasticity one");
  }
  return it->second(domain, tags);
}

}  // namespace volmesh::fem
