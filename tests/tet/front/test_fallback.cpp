// The fallback on forced stalls (stop_after) where the projection mesher cuts the cavity's
// faces: the tets around the cavity are refined to match, and the mesh stays valid; a cavity
// around a hole (another region) closes too.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/validity.hpp"
#include "split_checks.hpp"
#include "front_surfaces.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/tet_front/front.hpp"

namespace volmesh::tet {
namespace {

using test::expect_valid_with_splits;

std::vector<ProjectionSurface> from_file(const std::string& file) {
  const SurfaceDomain domain({LabelledSurface{read_surface(file), 0, file}});
  return {{domain.surface(0), domain.labels()[0], true}};
}

struct Case {
  std::string file;
  double size;
  long long stop_after;
};

class StoppedFront : public testing::TestWithParam<Case> {};

TEST_P(StoppedFront, IsClosedByRefiningAroundTheCutFaces) {
  const Case& c = GetParam();
  const auto surfaces = from_file(std::string(VOLMESH_CGAL_DATA "/meshes/") + c.file);
  const FrontResult r = tetrahedralize_by_front(surfaces, {.size = c.size, .stop_after = c.stop_after});
  expect_valid_with_splits(surfaces[0].surface, r);
  EXPECT_EQ(r.stats.stalls, 1);
  EXPECT_EQ(r.stats.front_tets, c.stop_after);
  EXPECT_GT(r.stats.split_cavity_faces, 0);  // the projection cut the cavity's faces
  EXPECT_GT(r.stats.refined_tets, 0);        // and the front's tets were refined to match
  EXPECT_GE(r.stats.steiner_points, r.stats.refined_tets);
}

INSTANTIATE_TEST_SUITE_P(Models, StoppedFront,
                         testing::Values(Case{"tripod.off", 0.3, 10}));

// The paper's example stopped early: the outer region's cavity has the inner cube as a hole,
// which the projection takes outward from the hole. Both regions close conformingly, with
// their volumes.
TEST(StoppedFront, ClosesACavityWithAHole) {
  const auto surfaces = test::surfaces_of(builtin_surfaces("cube-inclusion"));
  for (const long long stop_after : {0LL, 10LL, 40LL}) {
    const FrontResult r =
        tetrahedralize_by_front(surfaces, {.size = 2.0, .stop_after = stop_after, .improve = false});
    EXPECT_EQ(r.stats.stalls, 2) << stop_after;
    const ValidityReport v = check_validity(to_poly_mesh(r.mesh));
    EXPECT_TRUE(v.valid()) << stop_after << ": " << (v.problems.empty() ? "" : v.problems.front());
    ASSERT_EQ(v.region_volume.size(), 2u);
    EXPECT_NEAR(v.region_volume.at(2), 27.0, 27.0 * 1e-12);
    EXPECT_NEAR(v.region_volume.at(1), 512.0 - 27.0, 512.0 * 1e-12);
  }
}

}  // namespace
}  // namespace volmesh::tet
