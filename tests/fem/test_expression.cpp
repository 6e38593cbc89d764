// User expressions (muparser): values, the one-line errors naming the option and the
// position, concurrent evaluation, and the user problem's check of the source against the
// exact solution's Laplacian.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/fem/expression.hpp"
#include "volmesh/fem/problems.hpp"

namespace volmesh::fem {
namespace {

std::string error_of(const std::string& text, const std::string& what = "--exact") {
  try {
    parse_expression(text, what);
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(Expression, EvaluatesInXYZWithPiAndMuparserFunctions) {
  const Vec3 p(0.3, 0.5, 0.7);
  EXPECT_DOUBLE_EQ(parse_expression("sin(x)*exp(y*z)", "--exact")(p),
                   std::sin(0.3) * std::exp(0.35));
  // muparser's own _pi has 13 digits; ours is the double nearest to pi.
  EXPECT_EQ(parse_expression("pi", "--exact")(p), std::numbers::pi);
  EXPECT_EQ(parse_expression("_pi", "--exact")(p), std::numbers::pi);
  EXPECT_EQ(parse_expression("_e", "--exact")(p), std::numbers::e);
  EXPECT_DOUBLE_EQ(parse_expression("pi*x^2", "--exact")(p), std::numbers::pi * 0.09);
  EXPECT_DOUBLE_EQ(parse_expression("x > 0.4 ? 1 : -1", "--exact")(p), -1.0);
  EXPECT_DOUBLE_EQ(parse_expression("min(x, y) + max(y, z) + sqrt(z)", "--exact")(p),
                   0.3 + 0.7 + std::sqrt(0.7));
}

TEST(Expression, CopiesOfTheFunctionEvaluateIndependently) {
  const ScalarFunction f = parse_expression("x + 10*y + 100*z", "--exact");
  const ScalarFunction g = f;
  EXPECT_DOUBLE_EQ(f(Vec3(1, 2, 3)), 321.0);
  EXPECT_DOUBLE_EQ(g(Vec3(3, 2, 1)), 123.0);
  EXPECT_DOUBLE_EQ(f(Vec3(1, 2, 3)), 321.0);
}

TEST(Expression, ErrorsNameTheOptionAndThePosition) {
  const std::string missing = error_of("sin(x", "--source");
  EXPECT_NE(missing.find("--source"), std::string::npos) << missing;
  EXPECT_NE(missing.find("\"sin(x\""), std::string::npos) << missing;
  EXPECT_NE(missing.find("Missing parenthesis at position"), std::string::npos) << missing;

  const std::string unknown = error_of("sin(w)");
  EXPECT_NE(unknown.find("--exact"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("\"w\""), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("position 4"), std::string::npos) << unknown;

  EXPECT_NE(error_of("x+*2").find("position 2"), std::string::npos);
  EXPECT_NE(error_of("foo(x)").find("\"foo\""), std::string::npos);
  EXPECT_NE(error_of("  ").find("empty expression"), std::string::npos);
  for (const char* bad : {"sin(x", "x y", "x^", ")", ""})
    EXPECT_EQ(error_of(bad).find('\n'), std::string::npos) << bad;
}

TEST(Expression, ParallelEvaluationEqualsSerial) {
  const ScalarFunction f = parse_expression("sin(3*x)*cos(y+z^2) + exp(-x*y)", "--exact");
  const int n = 100000;
  std::vector<Vec3> points(n);
  for (int i = 0; i < n; ++i)
    points[i] = Vec3(std::sin(0.1 * i), std::cos(0.37 * i), 0.001 * i);
  std::vector<double> serial(n), parallel(n), copies(n);
  for (int i = 0; i < n; ++i) serial[i] = f(points[i]);
  tbb::parallel_for(0, n, [&](int i) { parallel[i] = f(points[i]); });
  tbb::parallel_for(0, n, [&](int i) {
    const ScalarFunction copy = f;  // copies share the per-thread parsers
    copies[i] = copy(points[i]);
  });
  EXPECT_EQ(serial, parallel);
  EXPECT_EQ(serial, copies);
}

class UserProblem : public ::testing::Test {
 protected:
  std::unique_ptr<Domain> box = make_builtin_domain("box");
  std::vector<std::string> tags{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  // −Δ(sin x e^{yz}) = sin x e^{yz} (1 − y² − z²)
  std::string exact = "sin(x)*exp(y*z)";
  std::string source = "sin(x)*exp(y*z)*(1 - y^2 - z^2)";
};

TEST_F(UserProblem, AMatchingSourceGivesNoWarning) {
  const UserPoissonProblem user = user_poisson_problem(exact, source, 1.0, *box, tags);
  EXPECT_EQ(user.warning, "");
  const UserPoissonProblem twice =
      user_poisson_problem(exact, "2*(" + source + ")", 2.0, *box, tags);
  EXPECT_EQ(twice.warning, "");
  ASSERT_EQ(user.problem.boundary.size(), tags.size());
  const Vec3 q(1.0, 0.25, 0.5);
  EXPECT_DOUBLE_EQ(user.problem.boundary.at("xmax").value(q), std::sin(1.0) * std::exp(0.125));
  EXPECT_DOUBLE_EQ(user.problem.conductivity.at(1), 1.0);
}

TEST_F(UserProblem, AMismatchedSourceIsReported) {
  const UserPoissonProblem wrong = user_poisson_problem(exact, "sin(x)*exp(y*z)", 1.0, *box, tags);
  EXPECT_NE(wrong.warning.find("--source does not match"), std::string::npos) << wrong.warning;
  // A relative error of 1e-3 in the source is caught, one of 1e-5 is not.
  const auto scaled = [&](const std::string& factor) {
    return user_poisson_problem(exact, factor + "*(" + source + ")", 1.0, *box, tags).warning;
  };
  EXPECT_NE(scaled("1.001"), "");
  EXPECT_EQ(scaled("1.00001"), "");
  // The conductivity is part of the check.
  EXPECT_NE(user_poisson_problem(exact, source, 2.0, *box, tags).warning, "");
}

TEST_F(UserProblem, HarmonicExactSolutionWithZeroSourceIsAccepted) {
  EXPECT_EQ(user_poisson_problem("exp(x)*cos(y) + x*y*z", "0", 1.0, *box, tags).warning, "");
}

TEST_F(UserProblem, WithoutSourceTheLaplacianIsTakenByFiniteDifferences) {
  const UserPoissonProblem user = user_poisson_problem(exact, "", 3.0, *box, tags);
  const ScalarFunction analytic = parse_expression(source, "--source");
  for (const Vec3& p : {Vec3(0.2, 0.3, 0.4), Vec3(0.9, 0.1, 0.8), Vec3(0.5, 0.5, 0.5)}) {
    EXPECT_NEAR(user.problem.source(p), 3.0 * analytic(p), 1e-7);
    const Vec3 g = user.problem.exact_gradient(p);
    const double e = std::exp(p.y() * p.z());
    EXPECT_NEAR(g.x(), std::cos(p.x()) * e, 1e-9);
    EXPECT_NEAR(g.y(), std::sin(p.x()) * p.z() * e, 1e-9);
    EXPECT_NEAR(g.z(), std::sin(p.x()) * p.y() * e, 1e-9);
  }
}

TEST_F(UserProblem, SourceAloneSolvesWithZeroBoundaryValues) {
  const UserPoissonProblem user = user_poisson_problem("", "1", 1.0, *box, tags);
  EXPECT_FALSE(user.problem.exact);
  EXPECT_DOUBLE_EQ(user.problem.boundary.at("zmin").value(Vec3(0.5, 0.5, 0.0)), 0.0);
  EXPECT_DOUBLE_EQ(user.problem.source(Vec3(0.5, 0.5, 0.5)), 1.0);
}

TEST_F(UserProblem, BadInputsAreInputErrors) {
  EXPECT_THROW(user_poisson_problem("", "", 1.0, *box, tags), InputError);
  EXPECT_THROW(user_poisson_problem(exact, source, 0.0, *box, tags), InputError);
  EXPECT_THROW(user_poisson_problem(exact, source, -1.0, *box, tags), InputError);
  try {
    user_poisson_problem(exact, "sin(x", 1.0, *box, tags);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--source"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace volmesh::fem
