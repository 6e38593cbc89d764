// The improver on poor cube meshes: the worst tet gets better and never worse, the boundary
// and the interface stay the same triangles exactly, every tet is positive by the exact test,
// and the result does not depend on the thread count.
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <algorithm>
#include <map>
#include <set>

#include "mesh_checks.hpp"
#include "poor_meshes.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/improve/improve.hpp"

namespace volmesh {
namespace {

using improve::improve_tet_mesh;
using improve::ImproveStats;

using test::boundary_triangles;
using test::exact_volume;
using test::expect_conforming;
using test::expect_exactly_positive;
using test::interface_triangles;

struct Improved {
  TetMesh before, after;
  ImproveStats stats;
};

Improved improved(const test::PoorCubeOptions& o) {
  Improved r;
  r.before = test::poor_cube(o);
  r.after = r.before;
  r.stats = improve_tet_mesh(r.after);
  return r;
}

TEST(Improve, PoorCubeGetsBetterAndStaysValid) {
  const Improved r = improved({});
  // The fixture is poor: slivers well under 10°.
  ASSERT_LT(r.stats.before.min_dihedral_deg, 10.0);
  EXPECT_GT(r.stats.after.min_dihedral_deg, r.stats.before.min_dihedral_deg + 5.0);
  EXPECT_LT(r.stats.after.max_dihedral_deg, r.stats.before.max_dihedral_deg);
  EXPECT_GE(r.stats.after.min_quality, r.stats.before.min_quality);
  EXPECT_LT(r.stats.after.below_10_degrees, r.stats.before.below_10_degrees);
  EXPECT_EQ(r.stats.after.tets, r.after.num_cells());
  EXPECT_GT(r.stats.operations.smoothed, 0);
  expect_exactly_positive(r.after);
  expect_conforming(r.after);
  EXPECT_EQ(boundary_triangles(r.after), boundary_triangles(r.before));
  EXPECT_EQ(exact_volume(r.after), exact_volume(r.before));
  EXPECT_EQ(r.after.boundary_tag, r.before.boundary_tag);
  EXPECT_EQ(r.after.tag_names, r.before.tag_names);
}

TEST(Improve, EveryFamilyTakesPart) {
  // A coarser, more jittered cube: its points have few tets, so the topological changes and
  // insertions are what helps.
  const Improved r = improved({.n = 6, .jitter = 0.45, .seed = 11});
  const auto& ops = r.stats.operations;
  EXPECT_GT(ops.smoothed, 0);
  EXPECT_GT(ops.flips_3_2 + ops.flips_4_4 + ops.edge_removals, 0);
  EXPECT_GT(ops.flips_2_3 + ops.face_removals, 0);
  EXPECT_GT(ops.contractions + ops.insertions, 0);
  expect_exactly_positive(r.after);
  expect_conforming(r.after);
}

TEST(Improve, InterfaceStaysAndRegionsKeepTheirVolumes) {
  const Improved r = improved({.two_regions = true});
  EXPECT_GT(r.stats.after.min_dihedral_deg, r.stats.before.min_dihedral_deg);
  EXPECT_EQ(interface_triangles(r.after), interface_triangles(r.before));
  EXPECT_FALSE(interface_triangles(r.after).empty());
  std::map<Index, mpq_class> before, after;
  for (Index c = 0; c < r.before.num_cells(); ++c)
    before[r.before.cell_region[c]] += test::exact_six_volume(r.before.points, r.before.cells[c]);
  for (Index c = 0; c < r.after.num_cells(); ++c)
    after[r.after.cell_region[c]] += test::exact_six_volume(r.after.points, r.after.cells[c]);
  EXPECT_EQ(after, before);
  expect_exactly_positive(r.after);
}

TEST(Improve, SameResultForAnyThreadCount) {
  std::vector<TetMesh> results;
  for (const int threads : {1, 2}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    results.push_back(improved({.two_regions = true}).after);
  }
  EXPECT_EQ(results[0].points, results[1].points);
  EXPECT_EQ(results[0].cells, results[1].cells);
  EXPECT_EQ(results[0].cell_region, results[1].cell_region);
}

TEST(Improve, GoodMeshIsLeftAlone) {
  const Improved r = improved({.n = 3, .jitter = 0.0});
  EXPECT_EQ(r.after.points, r.before.points);
  EXPECT_EQ(r.after.cells, r.before.cells);
}

TEST(Improve, BoundaryPointsSlideInTheirFaceOnly) {
  // The cube's twelve triangles as the surface: grid points inside a side slide in it.
  TriSurface cube;
  cube.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const auto& f : kHexFaces) {
    cube.triangles.push_back({f[0], f[1], f[2]});
    cube.triangles.push_back({f[0], f[2], f[3]});
  }
  TetMesh mesh = test::poor_cube({.n = 4, .jitter = 0.3, .face_jitter = 0.4});
  const TetMesh before = mesh;
  improve::ImproveOptions options;
  options.slides = improve::slides_on_surface(mesh, cube);
  const auto slides = std::count_if(options.slides.begin(), options.slides.end(), [](const auto& s) {
    return s.kind != improve::SlideKind::None;
  });
  EXPECT_GT(slides, 0);
  const ImproveStats stats = improve_tet_mesh(mesh, options);
  EXPECT_GT(stats.operations.slid, 0);
  EXPECT_GT(stats.after.min_quality, stats.before.min_quality);
  expect_exactly_positive(mesh);
  expect_conforming(mesh);
  EXPECT_EQ(exact_volume(mesh), exact_volume(before));
  // Every boundary point still on a side of the cube, exactly; the corners where they were.
  for (const auto& f : mesh.boundary_faces)
    for (const Index v : f) {
      const Vec3& p = mesh.points[v];
      const bool on_side = (p.array() == 0.0).any() || (p.array() == 1.0).any();
      EXPECT_TRUE(on_side) << p.transpose();
    }
}

TEST(Improve, RefusesAnInvertedTet) {
  TetMesh m = test::poor_cube({.n = 2, .jitter = 0.0});
  std::swap(m.cells[3][0], m.cells[3][1]);
  try {
    improve_tet_mesh(m);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tet 3 is flat or inverted"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace volmesh
