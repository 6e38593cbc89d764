// Signed-distance voxels: icospheres against the sphere within their own sagitta, a box
// exactly, the grid layout, determinism, progress, and refused surfaces.
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <random>

#include "test_surface_domain_support.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/grid_sdf.hpp"

namespace volmesh {
namespace {

using surface_test::box_surface;
using surface_test::icosphere;

TEST(SdfCompute, OctreeDims) {
  for (Index d : {3, 5, 9, 17, 33, 65, 129, 257, 1025}) EXPECT_TRUE(is_octree_dim(d)) << d;
  for (Index d : {-1, 0, 1, 2, 4, 6, 10, 16, 100, 128, 130}) EXPECT_FALSE(is_octree_dim(d)) << d;
}

TEST(SdfCompute, LayoutIsACubeAroundTheBoxWithTheMargin) {
  const Box3 box{{-1, 2, 0}, {3, 3, 0.5}};  // largest side 4, along x
  const VoxelGrid g = sdf_layout(box, 17, 0.05);
  EXPECT_EQ(g.dims, (std::array<Index, 3>{17, 17, 17}));
  EXPECT_TRUE(g.values.empty());
  EXPECT_EQ(g.spacing.x(), g.spacing.y());
  EXPECT_EQ(g.spacing.x(), g.spacing.z());
  EXPECT_GE(16 * g.spacing.x(), 4.4);
  EXPECT_LT(16 * g.spacing.x(), 4.4 * (1 + 1e-6));
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(g.origin[a], static_cast<float>(g.origin[a]));  // as .rawiv stores it
    EXPECT_EQ(g.spacing[a], static_cast<float>(g.spacing[a]));
    EXPECT_NEAR(g.origin[a] + 8 * g.spacing[a], box.centre()[a], 1e-6);
  }
  EXPECT_THROW(sdf_layout(box, 16, 0.05), std::invalid_argument);
  EXPECT_THROW(sdf_layout(box, 17, -0.1), std::invalid_argument);
  EXPECT_THROW(sdf_layout({Vec3::Zero(), Vec3::Zero()}, 17, 0.1), std::invalid_argument);
}

// The icosphere lies inside the unit sphere, at most its sagitta s = 1 - (nearest distance
// of a face's plane to the centre) away, so |SD - (1 - |p|)| <= s everywhere, with equality
// at the centre; s shrinks four-fold per refinement.
TEST(SdfCompute, IcospheresAreWithinTheirSagittaOfTheSphere) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  double previous = 1.0;
  for (int level = 0; level <= 4; ++level) {
    const TriSurface s = icosphere(level);
    double sagitta = 0.0;
    for (const auto& t : s.triangles) {
      const Vec3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
      sagitta = std::max(sagitta, 1.0 - std::abs((b - a).cross(c - a).normalized().dot(a)));
    }
    const SignedDistance sd(s, "icosphere");
    EXPECT_NEAR(sd(Vec3::Zero()), 1.0 - sagitta, 1e-15);
    double worst = 0.0;
    for (int i = 0; i < 3000; ++i) {
      const Vec3 p(u(rng), u(rng), u(rng));
      const double error = std::abs(sd(p) - (1.0 - p.norm()));
      EXPECT_LE(error, sagitta + 1e-15) << "level " << level << " at " << p.transpose();
      worst = std::max(worst, error);
    }
    EXPECT_GT(worst, 0.2 * sagitta);     // the bound is not vacuous
    EXPECT_LT(sagitta, 0.4 * previous);  // 3.1 times smaller at the first split, then 4
    previous = sagitta;
  }
}

double box_distance(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  const Vec3 below = lo - p, above = p - hi;
  const Vec3 out = below.cwiseMax(above);
  if (out.maxCoeff() <= 0.0) return -out.maxCoeff();  // inside: to the nearest face
  return -out.cwiseMax(0.0).norm();
}

TEST(SdfCompute, BoxDistancesAreExact) {
  const Vec3 lo(-1, -0.5, -0.25), hi(1, 0.5, 0.75);
  const SignedDistance sd(box_surface(lo, hi, 3), "box");
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    EXPECT_NEAR(sd(p), box_distance(p, lo, hi), 1e-12) << p.transpose();
  }
  VoxelGrid grid = sdf_layout(sd.bounds(), 33, 0.25);
  sd.sample(grid);
  for (Index k = 0; k < 33; ++k)
    for (Index j = 0; j < 33; ++j)
      for (Index i = 0; i < 33; ++i)
        ASSERT_NEAR(grid.at(i, j, k), box_distance(grid.point(i, j, k), lo, hi), 1e-6)
            << i << " " << j << " " << k;           // float samples
  EXPECT_EQ(sd(lo), 0.0);                           // a vertex
  EXPECT_LE(std::abs(sd({0.3, 0.5, 0.1})), 1e-16);  // on a face, to rounding
}

TEST(SdfCompute, SamplesDoNotDependOnTheThreadCount) {
  const SignedDistance sd(icosphere(3), "icosphere");
  std::vector<std::vector<float>> values;
  for (int threads : {1, 2}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    VoxelGrid grid = sdf_layout(sd.bounds(), 17, 0.1);
    std::vector<double> fractions;
    sd.sample(grid, [&](double f) { fractions.push_back(f); });
    EXPECT_EQ(fractions.size(), 17u);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_EQ(fractions.back(), 1.0);
    values.push_back(grid.values);
  }
  EXPECT_EQ(values[0], values[1]);
}

TEST(SdfCompute, RefusesASurfaceWithAHole) {
  TriSurface s = icosphere(1);
  s.triangles.pop_back();
  try {
    SignedDistance sd(s, "ball.stl");
    FAIL() << "a surface with a hole was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ball.stl: edge"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("hole"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace volmesh
