// Signed-distance voxels as a Domain: second-order crossings and first-order normals on a
// sampled sphere, exact roots of the trilinear interpolant, exact zeros, the box faces.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "volmesh/domain/grid.hpp"

namespace volmesh {
namespace {

const Vec3 kCentre(0.03, -0.02, 0.01);
constexpr double kRadius = 0.6;

// f = R - |x - c| (positive inside) on an n^3 grid over [-1, 1]^3.
VoxelGrid sphere_grid(Index n) {
  VoxelGrid grid;
  grid.dims = {n, n, n};
  grid.origin = Vec3::Constant(-1.0);
  grid.spacing = Vec3::Constant(2.0 / (n - 1));
  for (Index k = 0; k < n; ++k)
    for (Index j = 0; j < n; ++j)
      for (Index i = 0; i < n; ++i)
        grid.values.push_back(static_cast<float>(kRadius - (grid.point(i, j, k) - kCentre).norm()));
  return grid;
}

VoxelGrid constant_grid(std::array<Index, 3> dims, std::vector<float> values) {
  VoxelGrid grid;
  grid.dims = dims;
  grid.values = std::move(values);
  return grid;
}

struct SphereErrors {
  double position = 0.0, angle = 0.0;  // worst distance to the sphere; worst normal angle (radians)
};

SphereErrors sphere_errors(Index n) {
  const SdfGridDomain domain(sphere_grid(n));
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  SphereErrors worst;
  int count = 0;
  for (int s = 0; s < 300; ++s) {
    const Vec3 a = 0.95 * Vec3(g(rng), g(rng), g(rng)).normalized();
    const Vec3 b = kCentre + 0.4 * Vec3(g(rng), g(rng), g(rng)).normalized();
    const std::vector<Crossing> crossings = domain.crossings(a, b);
    EXPECT_EQ(crossings.size(), 1u);  // from outside to well inside
    for (const Crossing& c : crossings) {
      ++count;
      EXPECT_EQ(c.before, 0);
      EXPECT_EQ(c.after, 1);
      const Vec3 radial = (c.point - kCentre).normalized();
      worst.position = std::max(worst.position, std::abs((c.point - kCentre).norm() - kRadius));
      worst.angle =
          std::max(worst.angle, std::acos(std::min(1.0, c.normal.dot(-radial))));  // into the solid
      worst.angle =
          std::max(worst.angle, std::acos(std::min(1.0, domain.normal(c.point).dot(radial))));
    }
  }
  EXPECT_EQ(count, 300);
  return worst;
}

TEST(SdfGrid, SphereCrossingsAreSecondOrderAndNormalsFirstOrder) {
  const SphereErrors coarse = sphere_errors(17), fine = sphere_errors(33);
  const double h = 2.0 / 32;
  // Trilinear interpolation of R - |x| errs by about h^2 / 8 * (sum of curvatures 2/R) =
  // h^2 / (4R), which is what the crossings show (0.416 h^2 measured): bound with margin 2.
  EXPECT_LT(fine.position, h * h / (2 * kRadius)) << fine.position;
  EXPECT_LT(fine.position, 0.3 * coarse.position) << coarse.position << " -> " << fine.position;
  // Normals: first order asked; central differences on a smooth field do better (0.037 h).
  EXPECT_LT(fine.angle, 0.1 * h) << fine.angle;
  EXPECT_LT(fine.angle, 0.6 * coarse.angle) << coarse.angle << " -> " << fine.angle;
}

TEST(SdfGrid, RegionIsOneWhereTheFieldIsNonNegative) {
  const VoxelGrid grid = sphere_grid(17);
  const SdfGridDomain domain(grid);
  for (Index k = 0; k < 17; ++k)
    for (Index j = 0; j < 17; ++j)
      for (Index i = 0; i < 17; ++i)
        ASSERT_EQ(domain.region(grid.point(i, j, k)), grid.at(i, j, k) >= 0.0f ? 1 : 0);
  EXPECT_EQ(domain.region(Vec3(1.0 + 1e-9, 0, 0)), 0);
  EXPECT_EQ(domain.region(Vec3(NAN, 0, 0)), 0);
  EXPECT_EQ(domain.regions(), std::vector<Index>{1});
  const Box3 box = domain.bounds();
  EXPECT_TRUE((box.lo.array() <= (kCentre.array() - kRadius)).all() &&
              (box.hi.array() >= (kCentre.array() + kRadius)).all());
  EXPECT_TRUE((box.lo.array() >= (kCentre.array() - kRadius - 2 * 0.125)).all());
  const Vec3 p = kCentre + Vec3(0.3, 0.2, -0.1);  // away from the cone's tip at the centre
  EXPECT_NEAR(domain.value(p), kRadius - p.norm(), 0.125 * 0.125);

  // An exact zero is inside.
  std::vector<float> values(27, -1.0f);
  values[13] = 0.0f;
  const SdfGridDomain zero(constant_grid({3, 3, 3}, values));
  EXPECT_EQ(zero.region(Vec3(1, 1, 1)), 1);
  EXPECT_EQ(zero.region(Vec3(0.999, 1, 1)), 0);
  const SdfGridDomain outside(constant_grid({2, 2, 2}, std::vector<float>(8, -1.0f)));
  EXPECT_TRUE(outside.regions().empty());
  EXPECT_TRUE(outside.crossings(Vec3(-1, 0.5, 0.5), Vec3(2, 0.5, 0.5)).empty());
}

TEST(SdfGrid, FindsAllThreeRootsOfTheCubicInOneCell) {
  // Along the cell's diagonal f is the cubic with Bernstein coefficients c000, mean of the
  // three c100-type corners, mean of the c110-type, c111: here (t - 0.2)(t - 0.5)(t - 0.8).
  const SdfGridDomain domain(
      constant_grid({2, 2, 2}, {-0.08f, 0.14f, 0.14f, -0.14f, 0.14f, -0.14f, -0.14f, 0.08f}));
  const std::vector<Crossing> c = domain.crossings(Vec3::Zero(), Vec3::Ones());
  ASSERT_EQ(c.size(), 3u);
  const double expected[3] = {0.2, 0.5, 0.8};
  for (int r = 0; r < 3; ++r) {
    EXPECT_NEAR(c[r].t, expected[r], 1e-6);  // the float corner values move the roots by ~1e-8
    EXPECT_NEAR(domain.value(c[r].point), 0.0, 1e-15);
    EXPECT_EQ(c[r].before, r % 2 == 0 ? 0 : 1);
    EXPECT_EQ(c[r].after, r % 2 == 0 ? 1 : 0);
    // Normals point from `before` into `after`: along the segment here.
    EXPECT_GT(c[r].normal.dot(Vec3::Ones()), 0.0);
  }
  EXPECT_EQ(domain.region(Vec3::Zero()), 0);
  EXPECT_EQ(domain.region(Vec3::Ones()), 1);
}

TEST(SdfGrid, TouchingAnExactZeroIsOneTangentialCrossing) {
  // f = (y - 1) - (x - 1)^2 at the nodes of [0, 2]^3: the solid lies above a parabola whose
  // vertex, node (1, 1, 1), is an exact zero; the line y = z = 1 touches it there.
  std::vector<float> values;
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x) values.push_back(static_cast<float>((y - 1) - (x - 1) * (x - 1)));
  const SdfGridDomain domain(constant_grid({3, 3, 3}, values));
  EXPECT_EQ(domain.region(Vec3(1, 1, 1)), 1);
  EXPECT_EQ(domain.region(Vec3(0.999, 1, 1)), 0);
  const std::vector<Crossing> touch = domain.crossings(Vec3(0, 1, 1), Vec3(2, 1, 1));
  ASSERT_EQ(touch.size(), 1u);
  EXPECT_EQ(touch[0].t, 0.5);
  EXPECT_EQ(touch[0].point, Vec3(1, 1, 1));
  EXPECT_EQ(touch[0].before, 0);
  EXPECT_EQ(touch[0].after, 0);
  EXPECT_EQ(touch[0].normal, -Vec3::UnitY());  // out of the touching point's region, the solid
  // Starting on the zero: region(a) is 1 and the first crossing leaves at t = 0.
  const std::vector<Crossing> leave = domain.crossings(Vec3(1, 1, 1), Vec3(2, 1, 1));
  ASSERT_EQ(leave.size(), 1u);
  EXPECT_EQ(leave[0].t, 0.0);
  EXPECT_EQ(leave[0].before, 1);
  EXPECT_EQ(leave[0].after, 0);
  // Beside it: nothing below, two ordinary crossings above.
  EXPECT_TRUE(domain.crossings(Vec3(0, 0.99, 1), Vec3(2, 0.99, 1)).empty());
  EXPECT_EQ(domain.crossings(Vec3(0, 1.01, 1), Vec3(2, 1.01, 1)).size(), 2u);
}

TEST(SdfGrid, TheBoxIsAnInterfaceWhereTheSolidReachesIt) {
  const SdfGridDomain domain(constant_grid({2, 2, 2}, std::vector<float>(8, 1.0f)));
  const std::vector<Crossing> c = domain.crossings(Vec3(-1, 0.5, 0.25), Vec3(2, 0.5, 0.25));
  ASSERT_EQ(c.size(), 2u);
  EXPECT_DOUBLE_EQ(c[0].t, 1.0 / 3.0);
  EXPECT_EQ(c[0].point.x(), 0.0);
  EXPECT_EQ(c[0].normal, Vec3::UnitX());  // from outside into the box
  EXPECT_EQ(c[0].after, 1);
  EXPECT_DOUBLE_EQ(c[1].t, 2.0 / 3.0);
  EXPECT_EQ(c[1].point.x(), 1.0);
  EXPECT_EQ(c[1].normal, Vec3::UnitX());  // out of the box
  EXPECT_EQ(c[1].after, 0);
  EXPECT_EQ(domain.crossings(Vec3(0.5, 0.5, 0.5), Vec3(0.7, 0.2, 0.1)).size(), 0u);
}

TEST(SdfGrid, CrossingsChainOnRandomSegments) {
  const SdfGridDomain domain(sphere_grid(17));
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.3, 1.3);
  for (int s = 0; s < 200; ++s) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    Index current = domain.region(a);
    double t = 0.0;
    for (const Crossing& c : domain.crossings(a, b)) {
      ASSERT_EQ(c.before, current);
      ASSERT_GE(c.t, t);
      EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
      current = c.after;
      t = c.t;
    }
    EXPECT_EQ(current, domain.region(b));
  }
}

}  // namespace
}  // namespace volmesh
