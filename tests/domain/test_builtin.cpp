// The built-in domains: names, errors, regions and their exact volumes.
#include <gtest/gtest.h>

#include "test_analytic_support.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/analytic.hpp"
#include "volmesh/domain/builtin.hpp"

namespace volmesh {
namespace {

TEST(Builtin, NamesAndUnknownName) {
  EXPECT_EQ(builtin_domain_names(),
            (std::vector<std::string>{"ball", "box", "cube-inclusion", "layers6", "primitives",
                                      "schoenhardt", "thick-sphere", "twisted-prism:K:DEG"}));
  try {
    make_builtin_domain("nope");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "builtin:nope: unknown built-in domain (valid: ball, box, cube-inclusion, layers6, "
              "primitives, schoenhardt, thick-sphere, twisted-prism:K:DEG)");
  }
  EXPECT_THROW(builtin_region_volumes("nope"), InputError);
}

// Monte-Carlo (60,000 samples: 0.4% on the ball) and 140 x 140 exact chords; 140 is a
// multiple of 14 so that the faces of builtin:primitives' box lie between lines.
class BuiltinVolumes : public testing::TestWithParam<const char*> {};

TEST_P(BuiltinVolumes, MatchTheClosedForms) {
  const auto d = make_builtin_domain(GetParam());
  test::expect_region_volumes(*d, builtin_region_volumes(GetParam()), 60000, 140, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(All, BuiltinVolumes,
                         testing::Values("ball", "box", "cube-inclusion", "primitives",
                                         "thick-sphere", "schoenhardt", "twisted-prism:5:100"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (c == '-' || c == ':') c = '_';
                           return n;
                         });

TEST(Builtin, ClosedFormsOfThePaperScene) {
  // The seven regions of builtin:primitives add up to the union, by inclusion-exclusion.
  const auto v = builtin_region_volumes("primitives");
  double total = 0;
  for (const auto& [r, x] : v) {
    EXPECT_GT(x, 0.05) << "region " << r;
    total += x;
  }
  const double pi = std::numbers::pi;
  const double ball = 4 * pi / 3, box = 1.2 * 2.4 * 1.8, cylinder = pi * 0.25 * 2.8;
  EXPECT_NEAR(v.at(1) + v.at(3) + v.at(5) + v.at(7), ball, 1e-14);
  EXPECT_NEAR(v.at(2) + v.at(3) + v.at(6) + v.at(7), box, 1e-14);
  EXPECT_NEAR(v.at(4) + v.at(5) + v.at(6) + v.at(7), cylinder, 1e-14);
  EXPECT_GT(total, box);
}

TEST(Builtin, ThickSphereNamesItsSurfaces) {
  const auto d = make_builtin_domain("thick-sphere");
  const auto& shell = dynamic_cast<const AnalyticDomain&>(*d);
  EXPECT_EQ(shell.surface_name(Vec3(0.5, 0, 0)), "inner");
  EXPECT_EQ(shell.surface_name(Vec3(0, -1, 0)), "outer");
  const auto inclusion = make_builtin_domain("cube-inclusion");
  const auto& cubes = dynamic_cast<const AnalyticDomain&>(*inclusion);
  EXPECT_EQ(cubes.surface_name(Vec3(4, 4, 4)), "inclusion");
  EXPECT_EQ(cubes.surface_name(Vec3(0.1, 4, 4)), "outer");
}

TEST(Builtin, CubeInclusionIsRotatedByTheEulerAngles) {
  const auto d = make_builtin_domain("cube-inclusion");
  // R = Rz(pi/4) Rx(pi/6): the inclusion's local z axis is R e_z.
  const double pi = std::numbers::pi;
  const Vec3 axis(std::sin(pi / 6) * std::sin(pi / 4), -std::sin(pi / 6) * std::cos(pi / 4),
                  std::cos(pi / 6));
  const Vec3 centre = Vec3::Constant(4.0);
  EXPECT_EQ(d->region(centre + 1.49 * axis), 2);
  EXPECT_EQ(d->region(centre + 1.51 * axis), 1);
  EXPECT_LT((d->normal(centre + 1.49 * axis) - axis).norm(), 1e-14);
  EXPECT_EQ(d->bounds().lo, Vec3::Zero());
  EXPECT_EQ(d->bounds().hi, Vec3::Constant(8.0));
}

}  // namespace
}  // namespace volmesh
