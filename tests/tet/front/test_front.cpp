#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/quality/tet_metrics.hpp"
#include "front_checks.hpp"
#include "front_surfaces.hpp"
#include "volmesh/tet_front/front.hpp"

namespace volmesh::tet {
namespace {

using test::expect_valid;
using test::surfaces_of;

std::vector<ProjectionSurface> builtin(const std::string& name) {
  return surfaces_of(builtin_surfaces(name));
}

std::vector<ProjectionSurface> from_file(const std::string& file) {
  return surfaces_of({LabelledSurface{read_surface(file), 0, file}});
}

struct Figures {
  double min_dihedral = 180.0, max_dihedral = 0.0, max_radius_edge = 0.0;
};

Figures figures(const TetMesh& m) {
  Figures f;
  for (const auto& c : m.cells) {
    const TetMetrics q = tet_metrics(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]);
    f.min_dihedral = std::min(f.min_dihedral, q.min_dihedral_deg);
    f.max_dihedral = std::max(f.max_dihedral, q.max_dihedral_deg);
    f.max_radius_edge = std::max(f.max_radius_edge, q.radius_edge_ratio);
  }
  return f;
}

// The paper's example: two regions, the inner cube's surface between them kept on both sides.
TEST(TetFront, CubeInclusionAtTheSizeOfThePaper) {
  const auto surfaces = builtin("cube-inclusion");
  const FrontResult r = tetrahedralize_by_front(surfaces, {.size = 2.0});
  expect_valid(surfaces, r);
  EXPECT_EQ(r.stats.aux_deleted, r.stats.aux_points);  // every auxiliary point covered
  const Figures f = figures(r.mesh);
  EXPECT_GT(f.min_dihedral, 0.0);
  std::map<Index, int> regions;
  for (const Index region : r.mesh.cell_region) ++regions[region];
  EXPECT_EQ(regions.size(), 2u);
}

// The unit cube, each face in k x k squares split in two: a boundary of size 1/k, as the
// method expects.
TriSurface fine_box(int k) {
  TriSurface s;
  std::map<std::array<int, 3>, Index> index;
  const auto point = [&](std::array<int, 3> g) {
    const auto [it, added] = index.emplace(g, s.num_points());
    if (added) s.points.emplace_back(g[0] / double(k), g[1] / double(k), g[2] / double(k));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          // Corners of the square in the plane x[axis] = side, counter-clockwise seen from
          // outside.
          std::array<std::array<int, 3>, 4> q;
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          const std::array<std::array<int, 2>, 4> uv{{{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
          for (int c = 0; c < 4; ++c) {
            q[c][axis] = side * k;
            q[c][u] = uv[side ? c : 3 - c][0];
            q[c][v] = uv[side ? c : 3 - c][1];
          }
          const Index a = point(q[0]), b = point(q[1]), c = point(q[2]), d = point(q[3]);
          s.triangles.push_back({a, b, c});
          s.triangles.push_back({a, c, d});
        }
  return s;
}

TEST(TetFront, Box) {
  const auto surfaces = surfaces_of({LabelledSurface{fine_box(4), 0, "box"}});
  const FrontResult r = tetrahedralize_by_front(surfaces, {.size = 0.25});
  expect_valid(surfaces, r);
  EXPECT_GT(r.stats.new_nodes, 0);
}

TEST(TetFront, Sphere) {
  const auto surfaces = from_file(VOLMESH_CGAL_DATA "/meshes/sphere.off");
  const FrontResult r = tetrahedralize_by_front(surfaces, {.size = 0.2});
  expect_valid(surfaces, r);
}

// Stopped after a few tets, the front leaves a cavity the fallback closes conformingly.
TEST(TetFront, AStoppedFrontIsClosedConformingly) {
  const auto surfaces = surfaces_of({LabelledSurface{fine_box(2), 0, "box"}});
  const FrontResult r = tetrahedralize_by_front(surfaces, {.size = 0.5, .stop_after = 3});
  expect_valid(surfaces, r);
  EXPECT_EQ(r.stats.stalls, 1);
  EXPECT_EQ(r.stats.front_tets, 3);
  EXPECT_GT(r.stats.fallback_tets, 0);
}

TEST(TetFront, RefusesASizeNotPositiveOrTooSmall) {
  const auto surfaces = builtin("box");
  EXPECT_THROW(tetrahedralize_by_front(surfaces, {.size = 0.0}), InputError);
  EXPECT_THROW(tetrahedralize_by_front(surfaces, {.size = -1.0}), InputError);
  EXPECT_THROW(tetrahedralize_by_front(surfaces, {.size = 1e-6}), InputError);
}

}  // namespace
}  // namespace volmesh::tet
