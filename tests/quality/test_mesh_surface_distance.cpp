// surface_distance: a mesh's boundary and interfaces against a reference surface, on meshes
// whose distances are known in closed form, for both kinds of reference and both strategies.
#include <gtest/gtest.h>

#include <cmath>

#include "volmesh/core/boundary.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/quality/analytic_surfaces.hpp"

namespace volmesh {
namespace {

PolyMesh unit_cube(int n = 1) {
  return to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {n, n, n}));
}

// A triangulated reference seen only through distances and samples, so that the driver
// samples it instead of bounding it.
class SampledOnly final : public ReferenceSurface {
 public:
  explicit SampledOnly(const TriangulatedSurface& s) : s_(s) {}
  double distance(const Vec3& p) const override { return s_.distance(p); }
  std::size_t num_parts() const override { return s_.num_parts(); }
  void sample(std::size_t part, double spacing, std::vector<Vec3>& out) const override {
    s_.sample(part, spacing, out);
  }

 private:
  const TriangulatedSurface& s_;
};

// The regular octahedron with its corners on the unit sphere.
TriSurface octahedron() {
  TriSurface s;
  s.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const Index x : {0, 1})
    for (const Index y : {2, 3})
      for (const Index z : {4, 5}) s.triangles.push_back({x, y, z});
  return s;
}

// One unit cube against a box 0.1 taller: 0.1 both ways, all of it along the top, whose
// edges are in the box's feature group.
TEST(MeshSurfaceDistance, CubeAgainstATallerBox) {
  const AnalyticDomain taller({box(Vec3::Zero(), Vec3(1, 1, 1.1))}, {0, 1});
  const SurfaceDistance d =
      surface_distance(unit_cube(), AnalyticSurfaces(taller), {.tolerance = 0.05, .feature_band = 0.2});
  EXPECT_NEAR(d.all.mesh_to_surface.distance, 0.1, 1e-12);
  EXPECT_NEAR(d.all.surface_to_mesh.distance, 0.1, 1e-12);
  EXPECT_NEAR(d.all.surface_to_mesh.at.z(), 1.1, 1e-12);
  ASSERT_EQ(d.features.size(), 1u);
  EXPECT_NEAR(d.features[0].surface_to_mesh.distance, 0.1, 1e-12);  // the top edges are 0.1 off
  EXPECT_GT(d.features[0].surface_to_mesh.points, 0);
  EXPECT_LT(d.features[0].surface_to_mesh.points, d.all.surface_to_mesh.points);

  const AnalyticDomain same({box(Vec3::Zero(), Vec3::Ones())}, {0, 1});
  EXPECT_LT(surface_distance(unit_cube(), AnalyticSurfaces(same), {.tolerance = 0.05}).all.hausdorff(),
            1e-15);
  EXPECT_TRUE(surface_distance(unit_cube(), AnalyticSurfaces(same), {.tolerance = 0.05}).features.empty());
}

// The octahedron inscribed in the unit sphere: its face centres lie 1 - 1/sqrt(3) inside
// the sphere, the farthest points both ways. Sampled, each side is found within the
// tolerance below that; the face centres are samples, so the mesh side exactly.
TEST(MeshSurfaceDistance, SampledSidesAreWithinTheTolerance) {
  const PolyMesh mesh = [] {
    PolyMesh m;
    const TriSurface s = octahedron();
    m.points = s.points;
    m.cell_region = {1};
    for (const auto& t : s.triangles) {
      // Outward: the corners counter-clockwise seen from outside.
      const Vec3 n = (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]);
      const bool out = n.dot(s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) > 0;
      const std::array<Index, 3> loop = out ? t : std::array<Index, 3>{t[0], t[2], t[1]};
      m.add_face(loop, 0, kNoIndex, m.tag_index("boundary"));
    }
    return m;
  }();
  const double exact = 1.0 - 1.0 / std::sqrt(3.0);
  const AnalyticDomain ball({sphere(Vec3::Zero(), 1.0)}, {0, 1});
  for (const double tolerance : {0.2, 0.05}) {
    const SurfaceDistance d = surface_distance(mesh, AnalyticSurfaces(ball), {.tolerance = tolerance});
    EXPECT_NEAR(d.all.mesh_to_surface.distance, exact, 1e-12);
    EXPECT_LE(d.all.surface_to_mesh.distance, exact + 1e-12);
    EXPECT_GE(d.all.surface_to_mesh.distance, exact - tolerance);
  }
}

// The two strategies on one triangulated reference: bounded subdivision finds each side
// within its error bound, samples within their spacing, and neither above the truth.
TEST(MeshSurfaceDistance, BoundedAndSampledAgreeOnATriangulation) {
  const PolyMesh cube = unit_cube(3);
  const TriangulatedSurface reference(octahedron());
  const double error_bound = 1e-9, spacing = 0.02;
  const SurfaceDistance bounded = surface_distance(cube, reference, {.tolerance = error_bound});
  const SurfaceDistance sampled = surface_distance(cube, SampledOnly(reference), {.tolerance = spacing});
  for (const auto side : {&TwoSidedDistance::mesh_to_surface, &TwoSidedDistance::surface_to_mesh}) {
    EXPECT_LE((sampled.all.*side).distance, (bounded.all.*side).distance + error_bound);
    EXPECT_GE((sampled.all.*side).distance, (bounded.all.*side).distance - spacing);
  }
  // The cube's corner (1, 1, 1) is the farthest point of the mesh: sqrt(3) - 1/sqrt(3) from
  // the octahedron's face x + y + z = 1.
  EXPECT_NEAR(bounded.all.mesh_to_surface.distance, 2.0 / std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(bounded.all.mesh_to_surface.at.norm(), std::sqrt(3.0), 1e-9);
}

// Two cubes stacked as regions 1 and 2 against the two boxes of a multi-material domain:
// the interface is on the reference too. Measuring the boundary faces only leaves the
// interface's centre half a unit from the mesh.
TEST(MeshSurfaceDistance, InterfacesAreMeasuredUnlessLeftOut) {
  PolyMesh mesh = to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3(1, 1, 2), {1, 1, 2}));
  mesh.cell_region = {1, 2};
  const AnalyticDomain boxes = multi_material_domain(
      {box(Vec3::Zero(), Vec3::Ones(), "low"), box(Vec3(0, 0, 1), Vec3(1, 1, 2), "high")});
  const AnalyticSurfaces reference(boxes);
  EXPECT_LT(surface_distance(mesh, reference, {.tolerance = 0.05}).all.hausdorff(), 1e-15);
  const SurfaceDistance outer =
      surface_distance(mesh, reference, {.tolerance = 0.05, .interfaces = false});
  EXPECT_LT(outer.all.mesh_to_surface.distance, 1e-15);
  EXPECT_NEAR(outer.all.surface_to_mesh.distance, 0.5, 1e-12);
  EXPECT_NEAR(outer.all.surface_to_mesh.at.z(), 1.0, 1e-12);
}

TEST(MeshSurfaceDistance, RejectsAZeroToleranceAndAnEmptySurface) {
  const AnalyticDomain ball({sphere(Vec3::Zero(), 1.0)}, {0, 1});
  EXPECT_THROW(surface_distance(unit_cube(), AnalyticSurfaces(ball), {}), std::invalid_argument);
  EXPECT_THROW(TriangulatedSurface(TriSurface{}), std::invalid_argument);
}

}  // namespace
}  // namespace volmesh
