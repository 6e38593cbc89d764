// Volumes of single solids in tilted frames against their closed forms.
#include <gtest/gtest.h>

#include <numbers>

#include "test_analytic_support.hpp"
#include "volmesh/domain/analytic_csg.hpp"

namespace volmesh {
namespace {

constexpr double kPi = std::numbers::pi;
const Rigid kTilt{euler_zxz(0.3, 0.7, -0.4), Vec3(0.2, -0.1, 0.3)};

void expect_volume(const Solid& s, double exact) {
  test::expect_region_volumes(solid_domain(s), {{1, exact}}, 40000, 100, 2e-3);
}

TEST(AnalyticVolumes, Torus) {
  expect_volume(moved(torus(Vec3::Zero(), Vec3(1, 2, 2), 1.0, 0.3), kTilt),
                2 * kPi * kPi * 1.0 * 0.3 * 0.3);
}

TEST(AnalyticVolumes, Ellipsoid) {
  expect_volume(moved(ellipsoid(Vec3::Zero(), Vec3(1.0, 0.6, 0.4)), kTilt),
                4 * kPi / 3 * 1.0 * 0.6 * 0.4);
}

TEST(AnalyticVolumes, CylinderAndBox) {
  expect_volume(cylinder(Vec3(0, 0, 0), Vec3(1, 1, 1), 0.4), kPi * 0.16 * std::sqrt(3.0));
  expect_volume(moved(box(Vec3::Zero(), Vec3(1.0, 0.5, 2.0)), kTilt), 1.0);
}

TEST(AnalyticVolumes, SphereCutByAHalfSpace) {
  // The cap above z = 1/2 (height 1/2) is cut off the unit ball.
  const double cap = kPi * 0.25 * (3.0 - 0.5) / 3.0;
  expect_volume(Solid(sphere(Vec3::Zero(), 1.0)) & half_space(Vec3(0, 0, 0.5), Vec3::UnitZ()),
                4 * kPi / 3 - cap);
}

}  // namespace
}  // namespace volmesh
