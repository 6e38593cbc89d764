// Coarsening by edge contraction (coarsen.hpp) on a fine cube mesh: the counts fall, every
// tet stays positive by the exact test, the mesh conforming, the volume exact; without slides
// the boundary triangles stay exactly, and with them the boundary points inside the cube's
// sides go while the cube's surface stays the same point set.
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include "mesh_checks.hpp"
#include "poor_meshes.hpp"
#include "volmesh/improve/coarsen.hpp"

namespace volmesh {
namespace {

TriSurface unit_cube() {
  TriSurface cube;
  cube.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const auto& f : kHexFaces) {
    cube.triangles.push_back({f[0], f[1], f[2]});
    cube.triangles.push_back({f[0], f[2], f[3]});
  }
  return cube;
}

TEST(Coarsen, InteriorPointsGoBoundaryStays) {
  TetMesh mesh = test::poor_cube({.n = 5, .jitter = 0.2});
  const TetMesh before = mesh;
  const improve::CoarsenStats stats = improve::coarsen_tet_mesh(mesh);
  EXPECT_GT(stats.interior, 0);
  EXPECT_EQ(stats.boundary, 0);
  EXPECT_LT(mesh.num_cells(), before.num_cells());
  EXPECT_LT(mesh.num_points(), before.num_points());
  EXPECT_EQ(stats.tets_after, mesh.num_cells());
  test::expect_exactly_positive(mesh);
  test::expect_conforming(mesh);
  EXPECT_EQ(test::boundary_triangles(mesh), test::boundary_triangles(before));
  EXPECT_EQ(test::exact_volume(mesh), test::exact_volume(before));
}

TEST(Coarsen, SlidingBoundaryPointsGoWithinTheirSide) {
  TetMesh mesh = test::poor_cube({.n = 4, .jitter = 0.2});
  const TetMesh before = mesh;
  improve::CoarsenOptions options;
  options.slides = improve::slides_on_surface(mesh, unit_cube());
  const improve::CoarsenStats stats = improve::coarsen_tet_mesh(mesh, options);
  EXPECT_GT(stats.boundary, 0);
  EXPECT_LT(mesh.boundary_faces.size(), before.boundary_faces.size());
  test::expect_exactly_positive(mesh);
  test::expect_conforming(mesh);
  EXPECT_EQ(test::exact_volume(mesh), test::exact_volume(before));
  // Every boundary face lies in one side of the cube, exactly: a coordinate shared by its
  // three corners is 0 or 1.
  for (const auto& f : mesh.boundary_faces) {
    bool on_side = false;
    for (int axis = 0; axis < 3; ++axis) {
      const double c = mesh.points[f[0]][axis];
      on_side |= (c == 0.0 || c == 1.0) && mesh.points[f[1]][axis] == c && mesh.points[f[2]][axis] == c;
    }
    EXPECT_TRUE(on_side);
  }
  // The eight corners are still there.
  for (const Vec3& corner : unit_cube().points)
    EXPECT_NE(std::find(mesh.points.begin(), mesh.points.end(), corner), mesh.points.end());
}

TEST(Coarsen, SameResultForAnyThreadCount) {
  std::vector<TetMesh> results;
  for (const int threads : {1, 2}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    TetMesh mesh = test::poor_cube({.n = 4, .jitter = 0.3, .two_regions = true});
    improve::coarsen_tet_mesh(mesh);
    results.push_back(mesh);
  }
  EXPECT_EQ(results[0].points, results[1].points);
  EXPECT_EQ(results[0].cells, results[1].cells);
}

}  // namespace
}  // namespace volmesh
