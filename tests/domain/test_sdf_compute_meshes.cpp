// Signed distances of real meshes from libcgal-demo on a moderate grid, every sample against
// brute force: the sign against the generalized winding number (samples within 1e-9 of the
// surface skipped), the magnitude against the distance to every triangle.
#include <gtest/gtest.h>
#include <oneapi/tbb/parallel_for.h>

#include "test_surface_domain_support.hpp"
#include "volmesh/domain/grid_sdf.hpp"

namespace volmesh {
namespace {

struct Case {
  const char* mesh;
  Index dims;  // brute force costs samples x triangles: sized to a few seconds
};

class SdfComputeMesh : public testing::TestWithParam<Case> {};

TEST_P(SdfComputeMesh, EverySampleMatchesBruteForce) {
  const auto mesh = surface_test::cgal_mesh(GetParam().mesh);
  ASSERT_TRUE(mesh) << GetParam().mesh << " not found in " << VOLMESH_CGAL_DATA
                    << " (make test installs libcgal-demo)";
  const SignedDistance sd(*mesh, GetParam().mesh);
  // Not a (2^k+1) layout: an odd count that puts no sample on a symmetry plane.
  VoxelGrid grid;
  const Index n = GetParam().dims;
  const Box3 box = sd.bounds();
  grid.dims = {n, n, n};
  grid.spacing = box.size() * 1.2 / (n - 1);
  grid.origin = box.lo - 0.1 * box.size();
  sd.sample(grid);

  const std::int64_t count = static_cast<std::int64_t>(n) * n * n;
  const auto triangles = surface_test::corners(*mesh);
  std::vector<double> winding(count), distance(count);
  tbb::parallel_for(std::int64_t{0}, count, [&](std::int64_t v) {
    const Vec3 p = grid.point(v % n, v / n % n, v / n / n);
    winding[v] = surface_test::winding_number(triangles, p);
    distance[v] = surface_test::distance_to_surface(triangles, p);
  });
  int inside = 0, checked = 0;
  for (std::int64_t v = 0; v < count; ++v) {
    const Vec3 p = grid.point(v % n, v / n % n, v / n / n);
    // float samples of a distance computed in double
    ASSERT_NEAR(std::abs(grid.values[v]), distance[v], 1e-6 * (1.0 + distance[v])) << p.transpose();
    if (distance[v] < 1e-9) continue;
    ASSERT_LT(std::abs(winding[v] - std::round(winding[v])), 1e-6) << p.transpose();
    ++checked;
    inside += winding[v] > 0.5;
    ASSERT_EQ(grid.values[v] > 0.0f, winding[v] > 0.5)
        << p.transpose() << " winding " << winding[v];
  }
  EXPECT_GT(inside, count / 50);
  EXPECT_GT(checked, count - 10);
}

// The band sampling agrees with the full one: every sign, every value within the band, and
// farther out a bound between the band and the exact distance.
TEST_P(SdfComputeMesh, BandSamplesAreExactNearTheSurfaceAndBoundsFarther) {
  const auto mesh = surface_test::cgal_mesh(GetParam().mesh);
  ASSERT_TRUE(mesh) << GetParam().mesh << " not found in " << VOLMESH_CGAL_DATA
                    << " (make test installs libcgal-demo)";
  const SignedDistance sd(*mesh, GetParam().mesh);
  VoxelGrid full = sdf_layout(sd.bounds(), 65, 0.1);
  VoxelGrid band = full;
  sd.sample(full);
  const double width = 2.0 * full.spacing.maxCoeff();
  sd.sample_band(band, width);
  std::size_t far = 0;
  for (std::size_t v = 0; v < full.values.size(); ++v) {
    const float exact = full.values[v], bound = band.values[v];
    ASSERT_EQ(exact > 0.0f, bound > 0.0f) << v;
    if (std::abs(exact) <= width) {
      ASSERT_EQ(exact, bound) << v;
    } else if (exact != bound) {
      ++far;
      ASSERT_LE(std::abs(bound), std::abs(exact) * (1.0f + 1e-6f)) << v;
      ASSERT_GT(std::abs(bound), width * (1.0 - 1e-6)) << v;
    }
  }
  EXPECT_GT(far, full.values.size() / 4);  // many samples are far: the point of the band
}

INSTANTIATE_TEST_SUITE_P(Libcgal, SdfComputeMesh,
                         testing::Values(Case{"elephant.off", 15}, Case{"fandisk.off", 11},
                                         Case{"knot1.off", 13}),
                         [](const auto& info) {
                           std::string name = info.param.mesh;
                           return name.substr(0, name.find('.'));
                         });

}  // namespace
}  // namespace volmesh
