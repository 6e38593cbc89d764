#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "../domain/test_surface_domain_support.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/cutcell/cutcell.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/domain/surface.hpp"

namespace volmesh {
namespace {

// The interface triangles have their corners on the sphere (exact crossings) and lie within
// one cell, so within a ball of radius sqrt(3) h / 2 (the cell's circumradius): each lies in
// the sphere's cap of that radius, at most 3 h^2 / (8 R) below the sphere. The volume is then
// short by at most the area times that, a relative error of 3 (3 h^2 / (8 R)) / R = 9/8 h^2
// for the unit ball. The meshes stay at 0.23-0.30 h^2 at levels 2-5, well inside; the
// first-order midpoint variant, at 1.5 h^2 at level 4, would fail.
TEST(CutcellMesh, BallIsValidWithASecondOrderVolumeError) {
  const auto domain = make_builtin_domain("ball");
  const double exact = 4.0 / 3.0 * M_PI;
  for (int level = 2; level <= 5; ++level) {
    CutcellOptions options;
    options.octree.level = level;
    CutcellStats stats;
    const PolyMesh mesh = cutcell_mesh(*domain, options, &stats);
    const ValidityReport report = check_validity(mesh);
    EXPECT_TRUE(report.valid()) << "level " << level << ": " << report.problems.front();
    EXPECT_EQ(stats.bad_faces, 0) << "level " << level;
    const double h = std::ldexp(octree_root(*domain, options.octree).side, -level);
    EXPECT_LT(std::abs(report.total_volume / exact - 1.0), 9.0 / 8.0 * h * h) << "level " << level;
  }
}

// builtin:layers6 fills its unit box, which is then the octree's root: the box's faces are
// the root's, and grid vertices on them stay on them when moved off the layers. So the
// regions fill the box to rounding at every level (no gap, no overlap), which neither a box
// inside the root (its faces would cut cells) nor vertices moved off the box would give.
// Levels 3-5: level 6 takes 90 s under the sanitizers.
TEST(CutcellMesh, Layers6RegionsFillTheUnitBox) {
  const auto domain = make_builtin_domain("layers6");
  for (int level = 3; level <= 5; ++level) {
    CutcellOptions options;
    options.octree.level = level;
    const ValidityReport report = check_validity(cutcell_mesh(*domain, options));
    ASSERT_TRUE(report.valid()) << "level " << level;
    EXPECT_NEAR(report.total_volume, 1.0, 1e-10) << "level " << level;
  }
}

// The margin that puts the unit box's faces `offset` cells from the grid planes at `level`
// (the root is centred on the box: the faces lie 2^(level-1) 2m / (1 + 2m) cells in).
double margin_for_offset(int level, double offset) {
  const double r = (1.0 + offset) / std::ldexp(1.0, level - 1);
  return r / (2.0 * (1.0 - r));
}

// Faces passing a few hundredths of a cell from the grid planes: every grid vertex along them
// is moved off. Those next to the box's edges and corners go out across the faces near them,
// and the edge and corner points stay on the box (pushed a margin into the faces and cells,
// they would cut the cube's edges off). With the faces just inside the grid vertices
// (negative offsets), a vertex by a corner goes out across two of the three faces (across
// all three it would warp its leaves' faces across the third and move the corner), and the
// corner is the fan centre of its cell, not the face point on its vertical edge: the volume
// is the cube's to rounding.
TEST(CutcellMesh, BoxFacesNearGridPlanesKeepEdgesAndCorners) {
  const auto box = make_builtin_domain("box");
  for (const double offset : {0.01, 0.02, 0.03, -0.05, -0.07, -0.09}) {
    CutcellOptions options;
    options.octree.level = 3;
    options.octree.margin = margin_for_offset(3, offset);
    CutcellStats stats;
    const ValidityReport report = check_validity(cutcell_mesh(*box, options, &stats));
    ASSERT_TRUE(report.valid()) << offset;
    EXPECT_GT(stats.moved_vertices, 100) << offset;
    EXPECT_NEAR(report.total_volume, 1.0, 1e-10) << offset;
  }
  // layers6 there: the merged faces leave every cell valid (none of three faces).
  CutcellOptions options;
  options.octree.level = 4;
  options.octree.margin = margin_for_offset(4, 0.02);
  const ValidityReport report = check_validity(cutcell_mesh(*make_builtin_domain("layers6"), options));
  EXPECT_TRUE(report.valid()) << (report.problems.empty() ? "" : report.problems.front());
  EXPECT_NEAR(report.total_volume, 1.0, 1e-5);
}


// A prism: a counter-clockwise profile polygon in (u, v) with its caps' triangles, extruded
// over w in [0, 1] and placed by `at(u, v, w)` (a right-handed map). Closed, outward.
template <std::size_t N, std::size_t M>
TriSurface prism(const std::array<std::array<double, 2>, N>& profile,
                 const std::array<std::array<Index, 3>, M>& caps,
                 const std::function<Vec3(double, double, double)>& at) {
  const Index n = static_cast<Index>(N);
  TriSurface s;
  for (const double w : {0.0, 1.0})
    for (const auto& [u, v] : profile) s.points.push_back(at(u, v, w));
  for (const auto& [a, b, c] : caps) {
    s.triangles.push_back({a, c, b});
    s.triangles.push_back({a + n, b + n, c + n});
  }
  for (Index i = 0; i < n; ++i) {
    const Index j = (i + 1) % n;
    s.triangles.push_back({i, j, j + n});
    s.triangles.push_back({i, j + n, i + n});
  }
  return s;
}

// The unit cube without its part x, y > c: an L-shaped prism.
TriSurface l_shaped_prism(double c) {
  const std::array<std::array<double, 2>, 6> l{{{0, 0}, {1, 0}, {1, c}, {c, c}, {c, 1}, {0, 1}}};
  return prism(l, std::array<std::array<Index, 3>, 4>{{{0, 1, 2}, {0, 2, 3}, {0, 3, 5}, {3, 4, 5}}},
               [](double u, double v, double w) { return Vec3(u, v, w); });
}

// The root is centred on the bounding box, so the L's inner faces lie on grid planes and its
// inner edge on a grid line. Where that edge meets the top and bottom faces, the corner
// feature point is the edge point on the grid line (a fan around a new point there would
// leave two triangles of no area). The volume converges at second order: the cells at the
// inner edge are L-shaped.
TEST(CutcellMesh, LShapeWithItsInnerEdgeOnAGridLine) {
  const SurfaceDomain domain({{l_shaped_prism(0.5), 0, "L"}});
  double bound = 1e-2;
  for (int level = 3; level <= 6; ++level, bound /= 4.0) {
    CutcellOptions options;
    options.octree.level = level;
    const ValidityReport report = check_validity(cutcell_mesh(domain, options));
    ASSERT_TRUE(report.valid()) << "level " << level << ": " << report.problems.front();
    EXPECT_LT(std::abs(report.total_volume / 0.75 - 1.0), bound) << "level " << level;
  }
}


// The L's inner edge inside cells: the piece wrapping it is L-shaped, its centre beyond its
// own faces. It is split in two by the plane of one of the edge's faces rather than having
// its faces joined across the edge into bent polygons, which would cut the edge off: the
// planar L comes out exact.
TEST(CutcellMesh, LShapeSplitsItsPiecesAtTheInnerEdge) {
  const SurfaceDomain domain({{l_shaped_prism(0.37), 0, "L"}});
  const double exact = 1.0 - 0.63 * 0.63;
  for (const int level : {3, 5}) {
    CutcellOptions options;
    options.octree.level = level;
    CutcellStats stats;
    const ValidityReport report = check_validity(cutcell_mesh(domain, options, &stats));
    ASSERT_TRUE(report.valid()) << "level " << level << ": " << report.problems.front();
    EXPECT_GT(stats.split_cells, 0) << "level " << level;
    EXPECT_EQ(stats.bad_faces, 0) << "level " << level;
    EXPECT_NEAR(report.total_volume, exact, 1e-10) << "level " << level;
  }
}

// A block with a 60° ridge along x, narrower than a level-4 cell and lower than one, placed
// between the grid lines (margin 0: the root is the unit cube from z = -0.265): no cell edge
// crosses the ridge, whose cells see only the block's top, and their fans would cut it off
// (the ridge is 1.2e-3 of the volume). A crossing through their centre facing elsewhere than
// their edge points splits them down to level 5, where the edges see the ridge: the volume
// error stays below half the ridge's share (3.8e-4 at this level).
TEST(CutcellMesh, ARidgeHiddenInsideCellsIsRefinedTo) {
  const double top = 0.44, apex = 0.47, half_width = (apex - top) / std::sqrt(3.0), centre = 8.5 / 16.0;
  const std::array<std::array<double, 2>, 7> profile{{{0, 0}, {1, 0}, {1, top}, {centre + half_width, top},
                                                      {centre, apex}, {centre - half_width, top}, {0, top}}};
  const TriSurface s =
      prism(profile, std::array<std::array<Index, 3>, 5>{{{0, 1, 2}, {0, 2, 3}, {0, 3, 5}, {0, 5, 6}, {3, 4, 5}}},
            [](double y, double z, double x) { return Vec3(x, y, z); });
  const SurfaceDomain domain({{s, 0, "ridge"}});
  const double exact = top + half_width * (apex - top);
  CutcellOptions options;
  options.octree.level = 4;
  options.octree.margin = 0.0;
  CutcellStats stats;
  const ValidityReport report = check_validity(cutcell_mesh(domain, options, &stats));
  ASSERT_TRUE(report.valid()) << report.problems.front();
  EXPECT_GE(stats.max_leaf_level, 5);
  const double ridge = half_width * (apex - top) / exact;
  EXPECT_LT(std::abs(report.total_volume / exact - 1.0), 0.5 * ridge);
}

// A surface fan whose centre lands on the chord between the component's two face feature
// points (a flat half of a component split along a sharp edge) makes a boundary triangle
// with its corners in a line up to rounding: no normal to orient it, area 1e-20 where its
// sides are 0.01 long. The checker rejects such faces (area within 1e-12 of the longest side
// squared), and a cell's triangulations count one as inverted, so another is chosen.
// icosahedron.off at level 6 has such a cell.
TEST(CutcellMesh, NoBoundaryTriangleHasItsCornersInALine) {
  auto surface = surface_test::cgal_mesh("icosahedron.off");
  if (!surface) GTEST_SKIP() << "libcgal-demo is not installed";
  const SurfaceDomain domain({{std::move(*surface), 0, "icosahedron.off"}});
  CutcellOptions options;
  options.octree.level = 6;
  const PolyMesh mesh = cutcell_mesh(domain, options);
  const ValidityReport report = check_validity(mesh);
  EXPECT_TRUE(report.valid()) << report.problems.front();
  EXPECT_EQ(report.degenerate_faces, 0);
  double flattest = 1.0;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto loop = mesh.face(f);
    if (loop.size() != 3) continue;
    const double area = polygon_geometry(mesh.points, loop).area_vector.norm();
    flattest = std::min(flattest, flatness(mesh.points, loop, area));
  }
  EXPECT_GT(flattest, 1e-9);
}

}  // namespace

}  // namespace volmesh
