// The named problems: each exact solution satisfies its PDE (checked by finite differences
// at points inside the domain), boundary data are the exact solution's values, fluxes and
// tractions, and names and tags are checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/fem/problems.hpp"

namespace volmesh::fem {
namespace {

const std::vector<std::string> kBoxTags{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};

// Deterministic points of the box that the domain puts in a region.
std::vector<Vec3> points_inside(const Domain& domain, int count) {
  const Box3 b = domain.bounds();
  std::vector<Vec3> points;
  for (int i = 0; static_cast<int>(points.size()) < count; ++i) {
    const Vec3 t(std::fmod(0.618034 * i, 1.0), std::fmod(0.754878 * i + 0.1, 1.0),
                 std::fmod(0.569840 * i + 0.3, 1.0));
    const Vec3 p = b.lo + t.cwiseProduct(b.size());
    if (domain.region(p) != 0) points.push_back(p);
  }
  return points;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(ProblemLibrary, CatalogueNamesAreUniqueAndEachBuilds) {
  const std::vector<std::string> names = problem_names();
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
  const auto box = make_builtin_domain("box");
  const auto shell = make_builtin_domain("thick-sphere");
  for (const ProblemInfo& info : problem_catalogue()) {
    EXPECT_EQ(problem_kind(info.name), info.kind);
    if (info.kind == ProblemKind::poisson) {
      const PoissonProblem p = make_poisson_problem(info.name, *box, kBoxTags);
      EXPECT_EQ(p.boundary.size(), kBoxTags.size()) << info.name;
      EXPECT_EQ(p.conductivity.size(), 1u) << info.name;
      EXPECT_TRUE(p.to_true_boundary) << info.name;
    } else {
      const bool lame = info.name == "lame";
      const ElasticityProblem p =
          make_elasticity_problem(info.name, lame ? *shell : *box,
                                  lame ? std::vector<std::string>{"inner", "outer"} : kBoxTags);
      EXPECT_TRUE(p.exact && p.exact_gradient) << info.name;
      EXPECT_EQ(p.material.size(), 1u) << info.name;
    }
  }
}

TEST(ProblemLibrary, UnknownOrWrongKindNamesAreInputErrors) {
  const auto box = make_builtin_domain("box");
  const std::string unknown = error_of([&] { make_poisson_problem("sinus", *box, kBoxTags); });
  for (const std::string& name : problem_names())
    EXPECT_NE(unknown.find(name), std::string::npos) << unknown;
  EXPECT_NE(error_of([&] { make_poisson_problem("lame", *box, kBoxTags); }).find("elasticity"),
            std::string::npos);
  EXPECT_NE(error_of([&] { make_elasticity_problem("sine", *box, kBoxTags); }).find("Poisson"),
            std::string::npos);
  EXPECT_THROW(problem_kind(""), InputError);
}

// Fourth order: the Laplacian stencil is exact up to degree 5, the gradient's up to degree 4.
TEST(ProblemLibrary, FiniteDifferencesAreExactForLowDegreePolynomials) {
  const ScalarFunction quintic = [](const Vec3& p) {
    return std::pow(p.x(), 5) + p.x() * p.x() * std::pow(p.y(), 3) - 2.0 * std::pow(p.z(), 4);
  };
  const Vec3 p(0.3, -0.7, 1.1);
  const double laplacian = 20.0 * std::pow(p.x(), 3) + 2.0 * std::pow(p.y(), 3) +
                           6.0 * p.x() * p.x() * p.y() - 24.0 * p.z() * p.z();
  EXPECT_NEAR(finite_difference_laplacian(quintic, p, 1e-2), laplacian, 1e-9);
  const ScalarFunction quartic = [](const Vec3& p) {
    return std::pow(p.x(), 4) + p.x() * std::pow(p.y(), 3) - 2.0 * p.y() * std::pow(p.z(), 2);
  };
  const Vec3 gradient(4.0 * std::pow(p.x(), 3) + std::pow(p.y(), 3),
                      3.0 * p.x() * p.y() * p.y() - 2.0 * p.z() * p.z(), -4.0 * p.y() * p.z());
  EXPECT_LT((finite_difference_gradient(quartic, p, 1e-2) - gradient).norm(), 1e-10);
}

// −∇·(k∇u) = f with k constant per region, checked where the problem says it holds.
void expect_poisson_satisfied(const PoissonProblem& p, const Domain& domain) {
  for (const Vec3& x : points_inside(domain, 50)) {
    const double k = p.conductivity.at(domain.region(x));
    const double f = p.source ? p.source(x) : 0.0;
    EXPECT_NEAR(-k * finite_difference_laplacian(p.exact, x, 1e-3), f, 1e-5) << x.transpose();
    EXPECT_LT((finite_difference_gradient(p.exact, x, 1e-3) - p.exact_gradient(x)).norm(), 1e-8);
  }
}

TEST(ProblemLibrary, SineSatisfiesItsEquationAndBoundaryData) {
  const auto ball = make_builtin_domain("ball");
  const PoissonProblem p = make_poisson_problem("sine", *ball, {"sphere"});
  expect_poisson_satisfied(p, *ball);
  const Vec3 q = p.to_true_boundary(Vec3(0.3, -0.4, 0.8));
  EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  EXPECT_EQ(p.boundary.at("sphere").kind, ScalarBoundaryCondition::Kind::dirichlet);
  EXPECT_DOUBLE_EQ(p.boundary.at("sphere").value(q), p.exact(q));
  // Shifted: no factor vanishes on the unit cube's sides.
  EXPECT_GT(std::abs(p.exact(Vec3::Zero())), 0.01);
}

TEST(ProblemLibrary, SineNeumannGivesTheExactOutwardFluxOnAllButTheFirstTag) {
  const auto box = make_builtin_domain("box");
  const PoissonProblem p = make_poisson_problem("sine-neumann", *box, kBoxTags);
  expect_poisson_satisfied(p, *box);
  EXPECT_EQ(p.boundary.at("xmin").kind, ScalarBoundaryCondition::Kind::dirichlet);
  const std::vector<std::pair<std::string, Vec3>> sides{
      {"xmax", Vec3(1.0, 0.3, 0.6)}, {"ymin", Vec3(0.2, 0.0, 0.7)},
      {"ymax", Vec3(0.4, 1.0, 0.1)}, {"zmin", Vec3(0.8, 0.5, 0.0)},
      {"zmax", Vec3(0.6, 0.9, 1.0)}};
  const std::vector<Vec3> normals{Vec3::UnitX(), -Vec3::UnitY(), Vec3::UnitY(), -Vec3::UnitZ(),
                                  Vec3::UnitZ()};
  for (std::size_t i = 0; i < sides.size(); ++i) {
    const ScalarBoundaryCondition& bc = p.boundary.at(sides[i].first);
    EXPECT_EQ(bc.kind, ScalarBoundaryCondition::Kind::neumann);
    const Vec3 q = sides[i].second;
    EXPECT_NEAR(bc.value(q), p.exact_gradient(q).dot(normals[i]), 1e-14) << sides[i].first;
  }
  const auto ball = make_builtin_domain("ball");
  EXPECT_NE(error_of([&] { make_poisson_problem("sine-neumann", *ball, {"sphere"}); })
                .find("two boundary tags"),
            std::string::npos);
}

TEST(ProblemLibrary, PatchLinearIsHarmonicWithTheSameConductivityEverywhere) {
  const auto primitives = make_builtin_domain("primitives");
  const PoissonProblem p = make_poisson_problem("patch-linear", *primitives, {"ball", "box"});
  EXPECT_EQ(p.conductivity.size(), 7u);
  for (const auto& [region, k] : p.conductivity) EXPECT_EQ(k, 2.5) << region;
  expect_poisson_satisfied(p, *primitives);
  EXPECT_DOUBLE_EQ(p.exact(Vec3(1.0, 2.0, 3.0)), 1.0 + 2.0 - 2.0 + 9.0);
}

TEST(ProblemLibrary, MultiMaterialUsesTheRegionLabelAsConductivity) {
  const auto primitives = make_builtin_domain("primitives");
  const PoissonProblem p =
      make_poisson_problem("multi-material", *primitives, {"ball", "box", "cylinder"});
  ASSERT_EQ(p.conductivity.size(), 7u);
  for (const auto& [region, k] : p.conductivity) EXPECT_EQ(k, static_cast<double>(region));
  EXPECT_FALSE(p.exact);
  EXPECT_DOUBLE_EQ(p.source(Vec3(0.1, 0.2, 0.3)), 1.0);
  for (const auto& [tag, bc] : p.boundary) EXPECT_DOUBLE_EQ(bc.value(Vec3(0.0, 0.0, 1.0)), 0.0);
}

Eigen::Matrix3d stress(const ElasticityProblem& p, const Vec3& x) {
  const IsotropicMaterial m = p.material.begin()->second;
  const double lambda = m.young * m.poisson / ((1.0 + m.poisson) * (1.0 - 2.0 * m.poisson));
  const double mu = m.young / (2.0 * (1.0 + m.poisson));
  const Eigen::Matrix3d g = p.exact_gradient(x);
  const Eigen::Matrix3d strain = 0.5 * (g + g.transpose());
  return lambda * strain.trace() * Eigen::Matrix3d::Identity() + 2.0 * mu * strain;
}

// ∇·σ by fourth-order central differences of the exact stress.
Vec3 stress_divergence(const ElasticityProblem& p, const Vec3& x, double h) {
  Vec3 div = Vec3::Zero();
  for (int j = 0; j < 3; ++j) {
    const Vec3 e = h * Vec3::Unit(j);
    const Eigen::Matrix3d d = (-stress(p, x + 2 * e) + 8 * stress(p, x + e) -
                               8 * stress(p, x - e) + stress(p, x - 2 * e)) /
                              (12 * h);
    div += d.col(j);
  }
  return div;
}

TEST(ProblemLibrary, LameSatisfiesNavierAndTheSurfaceTractions) {
  const auto shell = make_builtin_domain("thick-sphere");
  const ElasticityProblem p = make_elasticity_problem("lame", *shell, {"outer", "inner"});
  EXPECT_DOUBLE_EQ(p.material.at(1).young, 1.0);
  EXPECT_DOUBLE_EQ(p.material.at(1).poisson, 0.3);
  for (const Vec3& x : points_inside(*shell, 40)) {
    EXPECT_LT(stress_divergence(p, x, 1e-3).norm(), 1e-7) << x.transpose();
    EXPECT_LT(p.exact(x).cross(x).norm(), 1e-15);  // radial
    for (int i = 0; i < 3; ++i) {
      const int axis = i;
      const ScalarFunction component = [&p, axis](const Vec3& y) { return p.exact(y)[axis]; };
      EXPECT_LT((finite_difference_gradient(component, x, 1e-3) -
                 p.exact_gradient(x).row(i).transpose())
                    .norm(),
                1e-8);
    }
  }
  const VectorBoundaryCondition& inner = p.boundary.at("inner");
  const VectorBoundaryCondition& outer = p.boundary.at("outer");
  ASSERT_EQ(inner.kind, VectorBoundaryCondition::Kind::traction);
  ASSERT_EQ(outer.kind, VectorBoundaryCondition::Kind::displacement);
  for (const Vec3& dir : {Vec3(1, 0, 0), Vec3(0.3, -0.4, 0.5).normalized(), Vec3(0, 0, -1)}) {
    // On r = 1/2 the outward normal of the shell is −dir: σn = −p n with p = 1.
    const Vec3 qi = p.to_true_boundary(0.52 * dir);
    EXPECT_NEAR((qi - 0.5 * dir).norm(), 0.0, 1e-15);
    EXPECT_LT((stress(p, qi) * -dir - dir).norm(), 1e-13);
    EXPECT_LT((inner.value(qi) - stress(p, qi) * -dir).norm(), 1e-13);
    // On r = 1 the exact solution is traction-free; its displacement is the Dirichlet data.
    const Vec3 qo = p.to_true_boundary(0.97 * dir);
    EXPECT_NEAR((qo - dir).norm(), 0.0, 1e-15);
    EXPECT_LT((stress(p, qo) * dir).norm(), 1e-13);
    EXPECT_EQ(outer.value(qo), p.exact(qo));
  }
  for (const std::vector<std::string>& tags : std::vector<std::vector<std::string>>{
           {"sphere"}, {"inner"}, {"inner", "outer", "cap"}})
    EXPECT_NE(error_of([&] { make_elasticity_problem("lame", *shell, tags); }).find("inner"),
              std::string::npos);
}

TEST(ProblemLibrary, ElasticPatchIsLinearWithoutBodyForce) {
  const auto box = make_builtin_domain("box");
  const ElasticityProblem p = make_elasticity_problem("elastic-patch", *box, kBoxTags);
  EXPECT_FALSE(p.body_force);
  for (const Vec3& x : points_inside(*box, 10)) {
    EXPECT_LT(stress_divergence(p, x, 1e-2).norm(), 1e-12);
    for (const auto& [tag, bc] : p.boundary) {
      EXPECT_EQ(bc.kind, VectorBoundaryCondition::Kind::displacement);
      EXPECT_EQ(bc.value(x), p.exact(x));
    }
    const Vec3 step(1e-3, -2e-3, 5e-4);
    EXPECT_LT((p.exact(x + step) - p.exact(x) - p.exact_gradient(x) * step).norm(), 1e-15);
  }
}

}  // namespace
}  // namespace volmesh::fem
