// The mesher's entry point (mesher.hpp): the stages in order on a sampled field, a valid mesh
// whose boundary lies on the surface, refinement when asked, refusals naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "fields.hpp"
#include "hex_checks.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/hexdc/mesher.hpp"

namespace volmesh {
namespace {

constexpr double kRadius = 0.8;
constexpr int kLevel = 4;
// Boundary nodes within this of the sphere (of its radius) are on it.
constexpr double kOnSurface = 1e-9;

VoxelGrid ball_field() {
  return test_fields::sample_paper_cube([](const Vec3& p) { return kRadius - p.norm(); });
}

Vec3 closest_on_sphere(const Vec3& p) { return kRadius * p.normalized(); }

HexdcOptions options_at(int level) {
  HexdcOptions options;
  options.level = level;
  options.source = "ball.rawiv";
  return options;
}

TEST(HexdcMesh, BallIsValidWithItsBoundaryOnTheSphere) {
  const HexdcResult r = hexdc_mesh(ball_field(), closest_on_sphere, options_at(kLevel));
  ASSERT_GT(r.mesh.num_cells(), 0);
  EXPECT_EQ(test_hexdc::invalid_hexes(r.mesh), 0);
  EXPECT_EQ(r.improved.cells, r.mesh.num_cells());
  EXPECT_EQ(r.improved.degenerate, 0);
  // Nothing thin, no hex's surface turning by kCurvedAngleDeg: the buffer layer puts one hex
  // per boundary quad on top of the uniform mesh.
  EXPECT_EQ(r.thin.thin_hexes, 0);
  EXPECT_EQ(r.thin.curved_hexes, 0);
  EXPECT_EQ(r.mesh.num_cells(), r.uniform.cells + r.pillow.pillow_hexes);
  EXPECT_EQ(r.pillow.pillow_hexes, static_cast<Index>(r.mesh.boundary_faces.size()));
  EXPECT_FALSE(r.refined.has_value());
  Index on_sphere = 0, boundary = 0;
  for (const auto& quad : r.mesh.boundary_faces)
    for (const Index v : quad) {
      ++boundary;
      const Vec3& p = r.mesh.points[static_cast<std::size_t>(v)];
      on_sphere += std::abs(p.norm() - kRadius) < kOnSurface * kRadius ? 1 : 0;
    }
  // The nodes the optimiser holds off the sphere (returning them would lower the worst measure)
  // are a few of its quads' corners.
  EXPECT_GE(on_sphere, boundary - 8 * r.optimisation.held_off_surface);
  EXPECT_GT(on_sphere, boundary * 99 / 100);
  // The sphere's volume, to the boundary quads' chords.
  const double sphere = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius;
  EXPECT_NEAR(test_hexdc::mesh_volume(r.mesh), sphere, 0.05 * sphere);
}

TEST(HexdcMesh, BoundaryLayerRefinementSplitsTheHexesNearTheSurface) {
  HexdcOptions options = options_at(kLevel - 1);
  const HexdcResult plain = hexdc_mesh(ball_field(), closest_on_sphere, options);
  options.refinement.boundary_layers = 1;
  const HexdcResult refined = hexdc_mesh(ball_field(), closest_on_sphere, options);
  ASSERT_TRUE(refined.refined.has_value());
  EXPECT_EQ(refined.refinement.hexes_before, plain.uniform.cells);
  EXPECT_GT(refined.refined->cells, plain.uniform.cells);
  EXPECT_GT(refined.mesh.num_cells(), plain.mesh.num_cells());
  EXPECT_EQ(test_hexdc::invalid_hexes(refined.mesh), 0);
}

TEST(HexdcMesh, RefusesAFieldWithNothingInsideByName) {
  const VoxelGrid empty = test_fields::sample_paper_cube([](const Vec3&) { return -1.0; });
  try {
    hexdc_mesh(empty, closest_on_sphere, options_at(kLevel));
    FAIL() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ball.rawiv: no sample"), std::string::npos) << e.what();
  }
}

TEST(HexdcMesh, RefusesBoundaryLayersOutOfRange) {
  HexdcOptions options = options_at(kLevel);
  options.refinement.boundary_layers = kMaxRefineLayers + 1;
  EXPECT_THROW(hexdc_mesh(ball_field(), closest_on_sphere, options), InputError);
  options.refinement.boundary_layers = -1;
  EXPECT_THROW(hexdc_mesh(ball_field(), closest_on_sphere, options), InputError);
}

}  // namespace
}  // namespace volmesh
