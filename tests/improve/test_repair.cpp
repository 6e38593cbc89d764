// The repair of flat and inverted tets (repair.hpp): interior points pushed through their
// neighbours' faces, as rounding can do to a thin mesh, and the repair makes every tet
// positive again by the exact test, the boundary and the volume unchanged.
#include <gtest/gtest.h>

#include "mesh_checks.hpp"
#include "poor_meshes.hpp"
#include "volmesh/improve/repair.hpp"

namespace volmesh {
namespace {

// Grid point (i, j, k) of test::poor_cube's n³ grid.
Index grid_point(int n, int i, int j, int k) { return static_cast<Index>((i * (n + 1) + j) * (n + 1) + k); }

Index count_not_positive(const TetMesh& m) {
  Index bad = 0;
  for (const auto& c : m.cells) bad += sgn(test::exact_six_volume(m.points, c)) <= 0;
  return bad;
}

TEST(Repair, InvertedTetsAroundMovedPointsArePositiveAgain) {
  constexpr int n = 4;
  TetMesh mesh = test::poor_cube({.n = n, .jitter = 0.0});
  const TetMesh before = mesh;
  // Two interior points pushed past a neighbour (inverting tets of their stars), one dropped
  // onto another point (flattening the tets holding both).
  mesh.points[grid_point(n, 1, 1, 1)] += Vec3(0.3, 0.05, -0.02);
  mesh.points[grid_point(n, 2, 3, 2)] += Vec3(-0.02, 0.3, 0.28);
  mesh.points[grid_point(n, 2, 2, 1)] = mesh.points[grid_point(n, 2, 1, 1)];
  const Index bad = count_not_positive(mesh);
  ASSERT_GT(bad, 0);
  const improve::RepairStats stats = improve::repair_flat_tets(mesh);
  EXPECT_EQ(stats.bad_before, bad);
  EXPECT_EQ(stats.bad_after, 0);
  EXPECT_GT(stats.smoothed + stats.flips + stats.contractions, 0);
  test::expect_exactly_positive(mesh);
  test::expect_conforming(mesh);
  EXPECT_EQ(test::boundary_triangles(mesh), test::boundary_triangles(before));
  EXPECT_EQ(test::exact_volume(mesh), test::exact_volume(before));
}

TEST(Repair, PositiveMeshIsLeftAlone) {
  TetMesh mesh = test::poor_cube({.n = 3});
  const TetMesh before = mesh;
  const improve::RepairStats stats = improve::repair_flat_tets(mesh);
  EXPECT_EQ(stats.bad_before, 0);
  EXPECT_EQ(mesh.points, before.points);
  EXPECT_EQ(mesh.cells, before.cells);
}

TEST(Repair, WhatCannotBeRepairedIsCounted) {
  // One inverted tet, all four corners on the boundary: nothing may move or go.
  TetMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.cells = {{1, 0, 2, 3}};
  mesh.cell_region = {1};
  test::add_boundary(mesh);
  const improve::RepairStats stats = improve::repair_flat_tets(mesh);
  EXPECT_EQ(stats.bad_before, 1);
  EXPECT_EQ(stats.bad_after, 1);
  EXPECT_EQ(mesh.cells, (std::vector<std::array<Index, 4>>{{1, 0, 2, 3}}));
}

}  // namespace
}  // namespace volmesh
