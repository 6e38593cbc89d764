#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <set>

#include "fields.hpp"
#include "hex_checks.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/hexdc/dual_contouring.hpp"
#include "volmesh/hexdc/hex_quality.hpp"
#include "volmesh/hexdc/pillow.hpp"
#include "volmesh/hexdc/optimise.hpp"

namespace volmesh {
namespace {

using test_hexdc::corners_of;
using test_hexdc::hex_volume;
using test_hexdc::invalid_hexes;
using test_hexdc::mesh_volume;

// Per hex, how many of its faces are boundary quads.
std::vector<int> boundary_faces_per_hex(const HexMesh& mesh) {
  std::set<std::array<Index, 4>> quads;
  for (auto q : mesh.boundary_faces) {
    std::sort(q.begin(), q.end());
    quads.insert(q);
  }
  std::vector<int> count(mesh.cells.size(), 0);
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    for (const auto& f : kHexFaces) {
      std::array<Index, 4> q{mesh.cells[h][f[0]], mesh.cells[h][f[1]], mesh.cells[h][f[2]],
                             mesh.cells[h][f[3]]};
      std::sort(q.begin(), q.end());
      count[h] += quads.count(q) > 0 ? 1 : 0;
    }
  return count;
}

// The old hexes come first and the pillow hexes after them: no old hex touches the boundary and
// every pillow hex has exactly one boundary face.
void expect_layered(const HexMesh& mesh, std::size_t old_hexes) {
  const std::vector<int> faces = boundary_faces_per_hex(mesh);
  for (std::size_t h = 0; h < faces.size(); ++h) EXPECT_EQ(faces[h], h < old_hexes ? 0 : 1) << h;
}

TEST(PillowBoundary, UnitCubeGetsSixPillowHexes) {
  HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {1, 1, 1});
  const auto boundary = mesh.boundary_faces;
  const PillowStats stats = pillow_boundary(mesh);
  EXPECT_EQ(mesh.cells.size(), 7u);
  EXPECT_EQ(mesh.points.size(), 16u);
  EXPECT_EQ(stats.boundary_nodes, 8);
  EXPECT_EQ(stats.pillow_hexes, 6);
  EXPECT_EQ(stats.multi_boundary_hexes_before, 1);
  EXPECT_EQ(stats.multi_boundary_hexes_after, 0);
  EXPECT_EQ(stats.invalid_hexes_after, 0);
  EXPECT_EQ(stats.shrunk_copies, 0);
  EXPECT_GT(stats.min_scaled_jacobian_after, 0.0);
  EXPECT_EQ(invalid_hexes(mesh), 0);
  EXPECT_NEAR(mesh_volume(mesh), 1.0, 1e-12);
  EXPECT_EQ(mesh.boundary_faces, boundary);
  expect_layered(mesh, 1);
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    EXPECT_GT(hex_volume(corners_of(mesh, h)), 0.0) << h;
}

TEST(PillowBoundary, BoxGridKeepsVolumeAndBoundaryNodes) {
  HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3(1.0, 2.0, 3.0), {2, 2, 2});
  const HexMesh original = mesh;
  const PillowStats stats = pillow_boundary(mesh);
  EXPECT_EQ(stats.boundary_nodes, 26);
  EXPECT_EQ(stats.pillow_hexes, 24);
  EXPECT_EQ(stats.multi_boundary_hexes_before, 8);
  EXPECT_EQ(stats.multi_boundary_hexes_after, 0);
  EXPECT_EQ(stats.invalid_hexes_after, 0);
  EXPECT_EQ(invalid_hexes(mesh), 0);
  EXPECT_NEAR(mesh_volume(mesh), 6.0, 1e-12);
  EXPECT_EQ(mesh.boundary_faces, original.boundary_faces);
  for (std::size_t v = 0; v < original.points.size(); ++v)
    EXPECT_EQ(mesh.points[v], original.points[v]) << v;
  expect_layered(mesh, original.cells.size());
}

TEST(PillowBoundary, RejectsBadOptions) {
  HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {1, 1, 1});
  EXPECT_THROW(pillow_boundary(mesh, {.offset_fraction = 0.0}), InputError);
  EXPECT_THROW(pillow_boundary(mesh, {.offset_fraction = 1.0}), InputError);
  EXPECT_THROW(pillow_boundary(mesh, {.halvings = -1}), InputError);
  EXPECT_THROW(pillow_boundary(mesh, {.feature_angle_deg = 181.0}), InputError);
  EXPECT_EQ(mesh.cells.size(), 1u);
}

struct Pillowed {
  HexMesh mesh;
  PillowStats pillow;
  OptimiseStats optimisation;
};

// The field's uniform mesh at `level`, pillowed (checked for its layer and volume) and optimised
// with its boundary fixed; the figures are printed.
Pillowed pillow_and_optimise(const char* name, const VoxelGrid& grid, int level) {
  Pillowed r{to_hex_mesh(hexdc_uniform(grid, level, nullptr)), {}, {}};
  const std::size_t old_hexes = r.mesh.cells.size();
  const double volume = mesh_volume(r.mesh);
  r.pillow = pillow_boundary(r.mesh);
  EXPECT_EQ(r.pillow.multi_boundary_hexes_after, 0);
  EXPECT_EQ(r.pillow.invalid_hexes_after, invalid_hexes(r.mesh));
  EXPECT_NEAR(mesh_volume(r.mesh), volume, 1e-9 * volume);
  expect_layered(r.mesh, old_hexes);
  r.optimisation = optimise_hexes(r.mesh, {});
  std::cout << name << " level " << level << ": hexes " << old_hexes << " + "
            << r.pillow.pillow_hexes << ", >=2 boundary faces "
            << r.pillow.multi_boundary_hexes_before << " -> 0, invalid "
            << r.pillow.invalid_hexes_before << " -> " << r.pillow.invalid_hexes_after << " -> "
            << invalid_hexes(r.mesh) << ", min SJ " << r.pillow.min_scaled_jacobian_before
            << " -> " << r.pillow.min_scaled_jacobian_after << " -> "
            << r.optimisation.min_scaled_jacobian_after << ", shrunk copies " << r.pillow.shrunk_copies
            << '\n';
  return r;
}

// The layer leaves no sphere hex invalid, and the optimiser raises the worst scaled Jacobian.
TEST(PillowBoundary, SphereHasNoHexWithTwoBoundaryFacesAndNoneInvalid) {
  const VoxelGrid grid =
      test_fields::sample_paper_cube([](const Vec3& p) { return 0.8 - p.norm(); });
  for (int level = 3; level <= 5; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    const Pillowed r = pillow_and_optimise("sphere", grid, level);
    EXPECT_EQ(r.pillow.invalid_hexes_before, 0);
    EXPECT_EQ(r.pillow.invalid_hexes_after, 0);
    EXPECT_GT(r.pillow.min_scaled_jacobian_after, 0.0);
    EXPECT_EQ(invalid_hexes(r.mesh), 0);
    EXPECT_GT(r.optimisation.min_scaled_jacobian_after, r.pillow.min_scaled_jacobian_before);
  }
}

// The torus's hexes invalid before pillowing stay so after it (the layer cannot unfold them by
// itself), but it frees them from the boundary, and the optimiser, the boundary fixed, unfolds
// them all.
TEST(PillowBoundary, TorusHexesPassTheCornerTetsAfterOptimisation) {
  const VoxelGrid grid = test_fields::sample_paper_cube(test_fields::torus_distance);
  for (int level = 3; level <= 5; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    const Pillowed r = pillow_and_optimise("torus", grid, level);
    EXPECT_EQ(invalid_hexes(r.mesh), 0);
    EXPECT_GT(r.optimisation.min_scaled_jacobian_after, 0.0);
  }
}

}  // namespace
}  // namespace volmesh
