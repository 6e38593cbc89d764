// Surface domains on real meshes from libcgal-demo: regions against a brute-force winding
// number, points 1e-12 off the surface, and crossings that chain from region(a) to region(b).
#include <gtest/gtest.h>

#include <random>

#include "test_surface_domain_support.hpp"
#include "volmesh/domain/surface.hpp"

namespace volmesh {
namespace {

using surface_test::cgal_mesh;

class SurfaceDomainMesh : public testing::TestWithParam<const char*> {};

TEST_P(SurfaceDomainMesh, RegionsMatchTheWindingNumber) {
  const auto mesh = cgal_mesh(GetParam());
  ASSERT_TRUE(mesh) << GetParam() << " not found in " << VOLMESH_CGAL_DATA
                    << " (make test installs libcgal-demo)";
  const SurfaceDomain d({{*mesh}});
  const Box3 box = d.bounds();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  const auto triangles = surface_test::corners(*mesh);
  int inside = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3 p = box.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(box.size());
    const double w = surface_test::winding_number(triangles, p);
    ASSERT_LT(std::abs(w - std::round(w)), 1e-6) << p.transpose();
    EXPECT_EQ(d.region(p), w > 0.5 ? 1 : 0) << p.transpose() << " winding " << w;
    inside += w > 0.5;
  }
  EXPECT_GT(inside, 10);
}

TEST_P(SurfaceDomainMesh, PointsOffTheSurfaceBy1e12AreOnTheirSide) {
  const auto mesh = cgal_mesh(GetParam());
  ASSERT_TRUE(mesh) << GetParam() << " not found in " << VOLMESH_CGAL_DATA
                    << " (make test installs libcgal-demo)";
  const SurfaceDomain d({{*mesh}});
  std::mt19937 rng(5);
  std::uniform_int_distribution<Index> pick(0, mesh->num_triangles() - 1);
  for (int i = 0; i < 200; ++i) {
    const auto& t = mesh->triangles[pick(rng)];
    const Vec3 &a = mesh->points[t[0]], &b = mesh->points[t[1]], &c = mesh->points[t[2]];
    const Vec3 centre = (a + b + c) / 3.0, n = (b - a).cross(c - a).normalized();
    EXPECT_EQ(d.region(centre - 1e-12 * n), 1);
    EXPECT_EQ(d.region(centre + 1e-12 * n), 0);
    EXPECT_EQ(d.region(a), 1);  // a vertex: on the surface
  }
}

TEST_P(SurfaceDomainMesh, CrossingsChainFromEndToEnd) {
  const auto mesh = cgal_mesh(GetParam());
  ASSERT_TRUE(mesh) << GetParam() << " not found in " << VOLMESH_CGAL_DATA
                    << " (make test installs libcgal-demo)";
  const SurfaceDomain d({{*mesh}});
  const Box3 box = d.bounds();
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  int total = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3 a = box.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(box.size());
    const Vec3 b = box.lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(box.size());
    const auto crossings = d.crossings(a, b);
    Index current = d.region(a);
    double t = 0.0;
    for (std::size_t k = 0; k < crossings.size(); ++k) {
      const Crossing& c = crossings[k];
      EXPECT_EQ(c.before, current);
      EXPECT_NE(c.before, c.after);  // no touches on random segments
      EXPECT_GE(c.t, t);
      const double next = k + 1 < crossings.size() ? crossings[k + 1].t : 1.0;
      EXPECT_EQ(d.region(a + 0.5 * (c.t + next) * (b - a)), c.after);
      // From `before` into `after`: along the segment, in or out.
      EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
      EXPECT_GT(c.normal.dot(b - a), 0.0);
      current = c.after;
      t = c.t;
    }
    EXPECT_EQ(current, d.region(b));
    total += static_cast<int>(crossings.size());
  }
  EXPECT_GT(total, 100);
}

INSTANTIATE_TEST_SUITE_P(Libcgal, SurfaceDomainMesh,
                         testing::Values("elephant.off", "fandisk.off", "knot1.off"));

}  // namespace
}  // namespace volmesh
