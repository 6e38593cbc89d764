// The global untangler and optimiser (optimise.hpp): a tangled grid untangles, a perturbed one
// gets a better worst corner, boundary nodes stay on the surface, and the result is the same
// for any thread count.
#include <gtest/gtest.h>

#include <oneapi/tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "fields.hpp"
#include "hex_checks.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/hexdc/dual_contouring.hpp"
#include "volmesh/hexdc/hex_quality.hpp"
#include "volmesh/hexdc/optimise.hpp"
#include "volmesh/hexdc/pillow.hpp"
#include "volmesh/hexdc/project.hpp"

namespace volmesh {
namespace {

using test_fields::box_distance;
using test_fields::closest_on_box;
constexpr double kHalfSide = test_fields::kBoxHalfSide;

using test_hexdc::corners_of;
using test_hexdc::invalid_hexes;

constexpr Index kCells = 4;  // per axis of the grids
constexpr double kRadius = 0.8;

double min_scaled_jacobian(const HexMesh& mesh) {
  double least = 1.0;
  for (std::size_t h = 0; h < mesh.cells.size(); ++h)
    least = std::min(least, hex_quality(corners_of(mesh, h)).scaled_jacobian);
  return least;
}

std::vector<bool> on_boundary(const HexMesh& mesh) {
  std::vector<bool> boundary(mesh.points.size(), false);
  for (const auto& quad : mesh.boundary_faces)
    for (const Index v : quad) boundary[static_cast<std::size_t>(v)] = true;
  return boundary;
}

// The unit grid with every interior node moved by `amplitude` cells in a fixed pseudo-random
// direction.
HexMesh perturbed_grid(double amplitude) {
  HexMesh mesh = structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {kCells, kCells, kCells});
  const std::vector<bool> boundary = on_boundary(mesh);
  const double h = 1.0 / kCells;
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (boundary[v]) continue;
    const auto s = static_cast<double>(v);
    mesh.points[v] += amplitude * h *
                      Vec3(std::sin(1.7 * s + 0.3), std::sin(2.3 * s + 1.1), std::sin(3.1 * s + 2.9));
  }
  return mesh;
}

TEST(OptimiseHexes, TangledGridUntangles) {
  HexMesh mesh = perturbed_grid(0.0);
  // Two interior nodes pushed through their neighbours: their hexes fold.
  const double h = 1.0 / kCells;
  mesh.points[static_cast<std::size_t>(1 + (kCells + 1) * (1 + (kCells + 1) * 1))] +=
      Vec3(1.4 * h, 1.3 * h, 1.2 * h);
  mesh.points[static_cast<std::size_t>(2 + (kCells + 1) * (2 + (kCells + 1) * 2))] +=
      Vec3(-1.3 * h, 0.2 * h, -1.5 * h);
  const std::vector<Vec3> boundary_before = mesh.points;
  ASSERT_GT(invalid_hexes(mesh), 0);
  const OptimiseStats stats = optimise_hexes(mesh, {});
  EXPECT_GT(stats.invalid_tets_before, 0);
  EXPECT_EQ(stats.invalid_tets_after, 0);
  EXPECT_EQ(invalid_hexes(mesh), 0);
  EXPECT_GT(min_scaled_jacobian(mesh), 0.5);
  // Without a surface the boundary stays where it was.
  const std::vector<bool> boundary = on_boundary(mesh);
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (boundary[v]) {
      EXPECT_EQ(mesh.points[v], boundary_before[v]) << v;
    }
}

TEST(OptimiseHexes, RaisesTheWorstScaledJacobianOfAPerturbedGrid) {
  HexMesh mesh = perturbed_grid(0.2);
  const double before = min_scaled_jacobian(mesh);
  ASSERT_EQ(invalid_hexes(mesh), 0);
  ASSERT_LT(before, 0.8);
  const OptimiseStats stats = optimise_hexes(mesh, {});
  EXPECT_EQ(invalid_hexes(mesh), 0);
  EXPECT_GT(stats.min_quality_after, stats.min_quality_before);
  // The grid is the optimum: the worst corner comes back near a right angle.
  EXPECT_GT(min_scaled_jacobian(mesh), 0.95);
  EXPECT_GT(min_scaled_jacobian(mesh), before);
}

// A field's uniform mesh at `level` with its buffer layer.
HexMesh pillowed_mesh(const std::function<double(const Vec3&)>& distance, int level) {
  HexMesh mesh = to_hex_mesh(hexdc_uniform(test_fields::sample_paper_cube(distance), level, nullptr));
  pillow_boundary(mesh);
  return mesh;
}

HexMesh ball_mesh(int level) {
  return pillowed_mesh([](const Vec3& p) { return kRadius - p.norm(); }, level);
}

Vec3 closest_on_sphere(const Vec3& p) { return kRadius * p.normalized(); }

TEST(OptimiseHexes, BoundaryNodesStayOnTheSurface) {
  HexMesh mesh = ball_mesh(3);
  const OptimiseStats stats = optimise_hexes(mesh, closest_on_sphere);
  EXPECT_EQ(invalid_hexes(mesh), 0);
  EXPECT_GT(stats.boundary_nodes, 0);
  EXPECT_EQ(stats.crease_nodes + stats.corner_nodes, 0);  // a sphere has no features
  // Every boundary node on the sphere but those held off it (whose return would lower the worst
  // measure), and those within a small fraction of the radius.
  const std::vector<bool> boundary = on_boundary(mesh);
  Index off = 0;
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (boundary[v]) {
      const double gap = std::abs(mesh.points[v].norm() - kRadius);
      off += gap > 1e-12 ? 1 : 0;
      EXPECT_LT(gap, 1e-3 * kRadius) << v;
    }
  EXPECT_EQ(off, stats.held_off_surface);
  EXPECT_LT(off, stats.boundary_nodes / 100);
  EXPECT_GT(min_scaled_jacobian(mesh), 0.5);
}

// The box's edges are creases and its corners corners: projected there first (as the mesher
// does), their nodes stay on them, the others on its faces, and the worst hexes are the buffer
// hexes at the box's corners (1/√3 at best).
TEST(OptimiseHexes, CreaseAndCornerNodesStayOnTheirFeatures) {
  HexMesh mesh = pillowed_mesh(box_distance, 3);
  project_boundary(mesh, closest_on_box);
  const OptimiseStats stats = optimise_hexes(mesh, closest_on_box);
  EXPECT_EQ(invalid_hexes(mesh), 0);
  EXPECT_EQ(stats.corner_nodes, 8);
  EXPECT_GT(stats.crease_nodes, 0);
  const std::vector<bool> boundary = on_boundary(mesh);
  Index corners = 0, on_edges = 0;
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (!boundary[v]) continue;
    const Vec3& p = mesh.points[v];
    EXPECT_NEAR((closest_on_box(p) - p).norm(), 0.0, 1e-12) << v;
    const auto at_side = (p.cwiseAbs().array() - kHalfSide).abs() < 1e-12;
    corners += at_side.count() == 3 ? 1 : 0;
    on_edges += at_side.count() == 2 ? 1 : 0;
  }
  EXPECT_EQ(corners, 8);
  EXPECT_EQ(on_edges, stats.crease_nodes);
  EXPECT_GT(min_scaled_jacobian(mesh), 0.55);
}

// The level-4 ball has enough hexes for several parallel blocks; a few iterations of each round
// go through every parallel sum (the equality needs no convergence).
TEST(OptimiseHexes, SameResultForAnyThreadCount) {
  constexpr int kIterations = 20;
  OptimiseOptions options;
  options.quality_iterations = kIterations;
  std::vector<std::vector<Vec3>> results;
  for (const int threads : {1, 2, 3}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    HexMesh mesh = ball_mesh(4);
    const OptimiseStats stats = optimise_hexes(mesh, closest_on_sphere, options);
    ASSERT_GT(stats.quality_iterations, options.sharpening_rounds);
    results.push_back(mesh.points);
  }
  EXPECT_EQ(results[0], results[1]);
  EXPECT_EQ(results[0], results[2]);
}

TEST(OptimiseHexes, RejectsBadOptions) {
  HexMesh mesh = perturbed_grid(0.0);
  const auto rejects = [&](const auto& change) {
    OptimiseOptions options;
    change(options);
    EXPECT_THROW(optimise_hexes(mesh, {}, options), InputError);
  };
  rejects([](OptimiseOptions& o) { o.quality_iterations = -1; });
  rejects([](OptimiseOptions& o) { o.theta = 1.0; });
  rejects([](OptimiseOptions& o) { o.softmin_sharpness = 0.0; });
  rejects([](OptimiseOptions& o) { o.feature_angle_deg = 200.0; });
}

}  // namespace
}  // namespace volmesh
