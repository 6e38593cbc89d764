// The tet meshers' boundaries: implicit domains triangulated by Mesh_3 (closed, manifold,
// outward, on the true surface, the enclosed volume converging) and surfaces remeshed by
// isotropic remeshing (sharp edges kept, the Hausdorff distance measured).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "volmesh/core/errors.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/surfacing/implicit.hpp"
#include "volmesh/surfacing/remesh.hpp"

namespace volmesh::surfacing {
namespace {

double enclosed_volume(const TriSurface& s) {
  double v = 0.0;
  for (const auto& t : s.triangles)
    v += s.points[t[0]].dot(s.points[t[1]].cross(s.points[t[2]]));
  return v / 6.0;
}

double longest_edge(const TriSurface& s) {
  double e = 0.0;
  for (const auto& t : s.triangles)
    for (int k = 0; k < 3; ++k) e = std::max(e, (s.points[t[k]] - s.points[t[(k + 1) % 3]]).norm());
  return e;
}

// Closed, manifold, consistently oriented, outward (check_surface flips nothing), no
// crossing triangles.
void expect_closed_outward(TriSurface s) {
  const SurfaceReport report = check_surface(s, "meshed");
  EXPECT_FALSE(report.flipped);
  EXPECT_EQ(report.components, 1);
  EXPECT_TRUE(report.self_intersections.empty());
  EXPECT_GT(report.volume, 0.0);
}

TEST(ImplicitSurface, TheUnitBallIsClosedOutwardOnTheSphereAndConverges) {
  const auto ball = make_builtin_domain("ball");
  const double exact = 4.0 / 3.0 * std::numbers::pi;
  double previous_error = 1.0;
  for (const double h : {0.4, 0.2, 0.1}) {
    const std::vector<InterfaceSurface> s = mesh_interfaces(*ball, h);
    ASSERT_EQ(s.size(), 1u) << h;
    EXPECT_EQ(s[0].inside, 1);
    EXPECT_EQ(s[0].outside, 0);
    expect_closed_outward(s[0].surface);
    for (const Vec3& p : s[0].surface.points) EXPECT_NEAR(p.norm(), 1.0, 1e-9) << h;
    // Edges of about h: none beyond 2h (the Delaunay balls have radius h / √3).
    EXPECT_LT(longest_edge(s[0].surface), 2.0 * h) << h;
    // An inscribed polyhedron of edge h misses a shell of depth about h² / 8: the volume
    // error is below 4π (h² / 8) and shrinks as h does.
    const double error = exact - enclosed_volume(s[0].surface);
    EXPECT_GT(error, 0.0) << h;
    EXPECT_LT(error, 4.0 * std::numbers::pi * h * h / 8.0) << h;
    EXPECT_LT(error, previous_error) << h;
    previous_error = error;
  }
}

TEST(ImplicitSurface, TheThickSphereGivesTheOuterSurfaceAndTheCavity) {
  const auto shell = make_builtin_domain("thick-sphere");
  const std::vector<InterfaceSurface> s = mesh_interfaces(*shell, 0.2);
  ASSERT_EQ(s.size(), 2u);
  int cavities = 0;
  for (const InterfaceSurface& i : s) {
    expect_closed_outward(i.surface);
    const double radius = i.inside == 0 ? 0.5 : 1.0;
    cavities += i.inside == 0;
    EXPECT_EQ(i.inside + i.outside, 1);
    for (const Vec3& p : i.surface.points) EXPECT_NEAR(p.norm(), radius, 1e-9);
  }
  EXPECT_EQ(cavities, 1);
}

TEST(ImplicitSurface, SameDomainAndSizeSameSurfaces) {
  const auto ball = make_builtin_domain("ball");
  const auto a = mesh_interfaces(*ball, 0.3), b = mesh_interfaces(*ball, 0.3);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a[0].surface.points, b[0].surface.points);
  EXPECT_EQ(a[0].surface.triangles, b[0].surface.triangles);
}

TEST(ImplicitSurface, BadSizesAreRefused) {
  const auto ball = make_builtin_domain("ball");
  EXPECT_THROW(mesh_interfaces(*ball, 0.0), InputError);
  EXPECT_THROW(mesh_interfaces(*ball, -1.0), InputError);
  EXPECT_THROW(mesh_interfaces(*ball, 1e-6), InputError);
}

// The cube [0.25, 0.75]^3 as 12 triangles: remeshed to edge 0.1 it keeps its 12 edges and
// corners (the volume stays 1/8), its faces get edges of about h, and the Hausdorff distance
// both ways is no more than the measuring error.
TEST(Remesh, ACubeKeepsItsEdgesAndVolume) {
  const TriSurface cube = read_surface(VOLMESH_TEST_DATA "/domains/inner_cube.off");
  const double h = 0.1;
  const Remeshed r = remesh_isotropic(cube, h);
  EXPECT_EQ(r.sharp_edges, 12);
  expect_closed_outward(r.surface);
  EXPECT_GT(r.surface.num_triangles(), 100);
  EXPECT_LT(longest_edge(r.surface), 4.0 / 3.0 * h + 1e-12);
  EXPECT_NEAR(enclosed_volume(r.surface), 0.125, 1e-12);
  EXPECT_LE(r.hausdorff_to_input, kHausdorffErrorPerEdge * h);
  EXPECT_LE(r.hausdorff_from_input, kHausdorffErrorPerEdge * h);
}

// A coarse ball (the Mesh_3 triangulation at h = 0.5) remeshed at 0.2: the new vertices lie
// on the input, the new triangles cut across its creases, so both distances are positive and
// below the coarse surface's own deviation from the sphere (its sagitta, 0.5² / 8 ≈ 0.03,
// taken twice).
TEST(Remesh, TheDistanceBothWaysIsMeasured) {
  const auto ball = make_builtin_domain("ball");
  const TriSurface coarse = mesh_interfaces(*ball, 0.5)[0].surface;
  const Remeshed r = remesh_isotropic(coarse, 0.2);
  expect_closed_outward(r.surface);
  EXPECT_GT(r.surface.num_triangles(), coarse.num_triangles());
  for (const double d : {r.hausdorff_to_input, r.hausdorff_from_input}) {
    EXPECT_GT(d, 0.0);
    EXPECT_LT(d, 2.0 * 0.5 * 0.5 / 8.0);
  }
  EXPECT_THROW(remesh_isotropic(coarse, 0.0), InputError);
}

}  // namespace
}  // namespace volmesh::surfacing
