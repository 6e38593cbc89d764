#include <gtest/gtest.h>

#include <cmath>

#include "fields.hpp"
#include "hex_checks.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/hexdc/dual_contouring.hpp"
#include "volmesh/hexdc/hex_quality.hpp"
#include "volmesh/hexdc/pillow.hpp"
#include "volmesh/hexdc/smoothing.hpp"
#include "volmesh/hexdc/untangle.hpp"

namespace volmesh {
namespace {

using test_hexdc::corners_of;

const std::array<Vec3, 8> kUnitCube{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0),
                                    Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 0, 1),
                                    Vec3(1, 1, 1), Vec3(0, 1, 1)};

Index invalid_hexes(const HexMesh& mesh) {
  Index n = 0;
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    n += hex_corner_tets_positive(corners_of(mesh, h)) ? 0 : 1;
  return n;
}

double min_scaled_jacobian(const HexMesh& mesh) {
  double least = 1.0;
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    least = std::min(least, hex_quality(corners_of(mesh, h)).scaled_jacobian);
  return least;
}

TEST(HexShapeQuality, IsOneInACubeAndNegativeInAFoldedHex) {
  EXPECT_NEAR(hex_shape_quality(kUnitCube), 1.0, 1e-12);
  std::array<Vec3, 8> folded = kUnitCube;
  folded[6] = Vec3(0.2, 0.2, 0.2);  // the top corner pushed through the bottom corner's tets
  EXPECT_FALSE(hex_corner_tets_positive(folded));
  EXPECT_LT(hex_shape_quality(folded), 0.0);
}

// Positive exactly when the hex passes the ten corner tets with a positive scaled Jacobian, and
// never above the scaled Jacobian: over cubes with their corners moved ever further.
TEST(HexShapeQuality, IsPositiveExactlyForValidHexes) {
  int valid = 0, invalid = 0;
  for (int n = 0; n < 200; ++n) {
    std::array<Vec3, 8> p = kUnitCube;
    const double amplitude = 0.005 * n;
    for (int c = 0; c < 8; ++c)
      for (int a = 0; a < 3; ++a) p[c][a] += amplitude * std::sin(1.7 * n + 3.1 * c + 5.3 * a);
    const double quality = hex_shape_quality(p);
    const double scaled_jacobian = hex_quality(p).scaled_jacobian;
    EXPECT_LE(quality, scaled_jacobian);
    const bool ok = hex_corner_tets_positive(p) && scaled_jacobian > 0.0;
    EXPECT_EQ(quality > 0.0, ok) << n;
    ++(ok ? valid : invalid);
  }
  EXPECT_GT(valid, 0);
  EXPECT_GT(invalid, 0);
}

// A 3x3x3 box whose two interior nodes (of the 2x2x2 inside) are pushed through their
// neighbours: the hexes around them fold, and the boundary holds the box.
TEST(UntangleHexes, UnfoldsPushedInteriorNodesAndKeepsTheBoundary) {
  HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {3, 3, 3});
  const std::vector<Vec3> boundary_before = [&] {
    std::vector<Vec3> points;
    for (const auto& quad : mesh.boundary_faces)
      for (const Index v : quad) points.push_back(mesh.points[v]);
    return points;
  }();
  Index pushed = 0;
  for (Vec3& p : mesh.points) {
    const bool interior = (p.array() > 0.0).all() && (p.array() < 1.0).all();
    if (interior && pushed++ < 2) p += Vec3(0.2, 0.15, -0.18);
  }
  ASSERT_EQ(pushed, 8);
  ASSERT_GT(invalid_hexes(mesh), 0);

  const UntangleStats stats = untangle_hexes(mesh);
  EXPECT_EQ(stats.invalid_hexes_after, 0);
  EXPECT_EQ(invalid_hexes(mesh), 0);
  EXPECT_GT(stats.min_quality_after, stats.min_quality_before);
  EXPECT_GT(min_scaled_jacobian(mesh), 0.5);
  std::size_t i = 0;
  for (const auto& quad : mesh.boundary_faces)
    for (const Index v : quad) EXPECT_EQ(mesh.points[v], boundary_before[i++]);
}

TEST(UntangleHexes, NeverLowersTheLeastQualityNorInvalidatesAHex) {
  HexMesh mesh = to_hex_mesh(
      hexdc_uniform(test_fields::sample_paper_cube(test_fields::torus_distance), 4, nullptr));
  pillow_boundary(mesh);
  std::vector<bool> valid_before;
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    valid_before.push_back(hex_corner_tets_positive(corners_of(mesh, h)));
  const UntangleStats stats = untangle_hexes(mesh);
  EXPECT_GE(stats.min_quality_after, stats.min_quality_before);
  EXPECT_LE(stats.invalid_hexes_after, stats.invalid_hexes_before);
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    if (valid_before[h]) EXPECT_TRUE(hex_corner_tets_positive(corners_of(mesh, h))) << h;
}

// The torus at level 4 through the mesher's stages: pillowing and smoothing leave hexes failing
// the ten corner tets on its inner, concave side (6); the optimisation unfolds all but those
// held by their fixed boundary quads (2).
TEST(UntangleHexes, TorusAtLevelFourEndsValid) {
  HexMesh mesh = to_hex_mesh(
      hexdc_uniform(test_fields::sample_paper_cube(test_fields::torus_distance), 4, nullptr));
  pillow_boundary(mesh);
  const SmoothingStats smoothing = smooth_hexes(mesh);
  ASSERT_GT(smoothing.invalid_hexes_after, 0);
  const UntangleStats stats = untangle_hexes(mesh);
  std::cout << "torus level 4: invalid " << stats.invalid_hexes_before << " -> "
            << stats.invalid_hexes_after << ", min scaled Jacobian " << min_scaled_jacobian(mesh)
            << "\n";
  EXPECT_EQ(invalid_hexes(mesh), stats.invalid_hexes_after);
  EXPECT_LE(stats.invalid_hexes_after, smoothing.invalid_hexes_after / 3);
}

TEST(UntangleHexes, RejectsBadOptions) {
  HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {2, 2, 2});
  EXPECT_THROW(untangle_hexes(mesh, {.target_quality = 0.0}), InputError);
  EXPECT_THROW(untangle_hexes(mesh, {.sweeps = -1}), InputError);
  EXPECT_THROW(untangle_hexes(mesh, {.initial_step = 0.1, .final_step = 0.2}), InputError);
  EXPECT_THROW(untangle_hexes(mesh, {.feature_angle_deg = 200.0}), InputError);
}

}  // namespace
}  // namespace volmesh
