// The input's sharp features (features.hpp) and the buffer layer following them
// (feature_layer.hpp): creases on chains of hex edges, corners on hex nodes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include <oneapi/tbb/global_control.h>

#include "fields.hpp"
#include "hex_checks.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/hexdc/features.hpp"
#include "volmesh/hexdc/mesher.hpp"
#include "volmesh/hexdc/optimise.hpp"
#include "volmesh/hexdc/pillow.hpp"
#include "volmesh/hexdc/project.hpp"

namespace volmesh {
namespace {

using test_fields::kBoxHalfSide;

// The box of test_fields::box_distance as 12 outward triangles.
TriSurface box_surface() {
  TriSurface s;
  for (int k = 0; k < 8; ++k)
    s.points.emplace_back((k & 1) ? kBoxHalfSide : -kBoxHalfSide,
                          (k & 2) ? kBoxHalfSide : -kBoxHalfSide,
                          (k & 4) ? kBoxHalfSide : -kBoxHalfSide);
  // Each face as a quad of corner indices, counter-clockwise seen from outside.
  const std::array<std::array<Index, 4>, 6> faces{{{0, 2, 3, 1},
                                                   {4, 5, 7, 6},
                                                   {0, 1, 5, 4},
                                                   {2, 6, 7, 3},
                                                   {0, 4, 6, 2},
                                                   {1, 3, 7, 5}}};
  for (const auto& f : faces) {
    s.triangles.push_back({f[0], f[1], f[2]});
    s.triangles.push_back({f[0], f[2], f[3]});
  }
  return s;
}

TEST(SharpFeatures, BoxHasTwelveCreasesAndEightCorners) {
  const SurfaceFeatures f = sharp_features(box_surface(), feature_angle_degrees());
  EXPECT_EQ(f.corners.size(), 8U);
  ASSERT_EQ(f.creases.size(), 12U);
  for (const auto& crease : f.creases) {
    ASSERT_EQ(crease.size(), 2U);  // the diagonals of the faces are flat
    EXPECT_NEAR((crease[1] - crease[0]).norm(), 2.0 * kBoxHalfSide, 1e-12);
  }
}

TEST(SharpFeatures, RightAnglesBelowTheFeatureAngleAreNoCreases) {
  const SurfaceFeatures f = sharp_features(box_surface(), 90.0 + 1e-6);
  EXPECT_TRUE(f.creases.empty());
  EXPECT_TRUE(f.corners.empty());
}

TEST(SharpFeatures, RejectsAnAngleOutOfRange) {
  EXPECT_THROW(sharp_features(box_surface(), -1.0), InputError);
}

// Every face of the mesh on one or two hexes, the ones on one exactly its boundary quads.
void expect_conforming(const HexMesh& mesh) {
  std::map<std::array<Index, 4>, int> count;
  const auto key = [](std::array<Index, 4> q) {
    std::sort(q.begin(), q.end());
    return q;
  };
  for (const auto& cell : mesh.cells)
    for (const auto& f : kHexFaces) ++count[key({cell[f[0]], cell[f[1]], cell[f[2]], cell[f[3]]})];
  Index once = 0;
  for (const auto& [face, n] : count) {
    EXPECT_LE(n, 2);
    once += n == 1 ? 1 : 0;
  }
  EXPECT_EQ(once, static_cast<Index>(mesh.boundary_faces.size()));
  for (const auto& quad : mesh.boundary_faces) EXPECT_EQ(count[key(quad)], 1);
}

HexMesh box_hexes(int level) {
  const VoxelGrid field = test_fields::sample_paper_cube(test_fields::box_distance);
  return to_hex_mesh(hexdc_uniform(field, level, nullptr));
}

TEST(FeatureLayer, BoxLayerConformsWithAChainPerCrease) {
  HexMesh mesh = box_hexes(4);
  const SurfaceFeatures features = sharp_features(box_surface(), feature_angle_degrees());
  PillowOptions options;
  options.features = &features;
  FeatureLayer layer;
  const PillowStats stats = pillow_boundary(mesh, options, &layer);
  expect_conforming(mesh);
  EXPECT_EQ(layer.chains.size(), 12U);
  // The corners, then each chain's nodes between them.
  std::size_t inner = 0;
  for (const FeatureChain& chain : layer.chains) inner += chain.nodes.size() - 2;
  EXPECT_EQ(layer.pinned.size(), 8U + inner);
  EXPECT_EQ(layer.patches_pillowed, 0);
  EXPECT_EQ(stats.invalid_hexes_after, 0);
}

TEST(FeatureLayer, BoxPatchesArePillowedAgainAndStayValid) {
  HexMesh mesh = box_hexes(4);
  const SurfaceFeatures features = sharp_features(box_surface(), feature_angle_degrees());
  PillowOptions options;
  options.features = &features;
  options.follow_features = true;
  FeatureLayer layer;
  const Index quads_before_layer = [&] {
    HexMesh plain = mesh;
    pillow_boundary(plain);
    return static_cast<Index>(plain.boundary_faces.size());
  }();
  const PillowStats stats = pillow_boundary(mesh, options, &layer);
  expect_conforming(mesh);
  EXPECT_EQ(layer.patches_pillowed, 6);
  // Each face's layer once more, and a strip of quads along each side of every chain edge.
  Index chain_edges = 0;
  for (const FeatureChain& chain : layer.chains) chain_edges += static_cast<Index>(chain.nodes.size()) - 1;
  EXPECT_EQ(static_cast<Index>(mesh.boundary_faces.size()), quads_before_layer + 2 * chain_edges);
  EXPECT_EQ(stats.invalid_hexes_after, 0);
  EXPECT_EQ(test_hexdc::invalid_hexes(mesh), 0);
}

// The largest distance from the segment a-b to the mesh's boundary edges, sampled.
double distance_to_boundary_edges(const HexMesh& mesh, const Vec3& a, const Vec3& b) {
  constexpr int kSamples = 32;
  double worst = 0.0;
  for (int k = 0; k <= kSamples; ++k) {
    const Vec3 p = a + (b - a) * (static_cast<double>(k) / kSamples);
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& quad : mesh.boundary_faces)
      for (std::size_t c = 0; c < 4; ++c) {
        const Vec3& u = mesh.points[static_cast<std::size_t>(quad[c])];
        const Vec3& w = mesh.points[static_cast<std::size_t>(quad[(c + 1) % 4])];
        const double t = std::clamp((p - u).dot(w - u) / (w - u).squaredNorm(), 0.0, 1.0);
        nearest = std::min(nearest, (p - (u + t * (w - u))).norm());
      }
    worst = std::max(worst, nearest);
  }
  return worst;
}

Eigen::Matrix3d turning(double turn) {
  return Eigen::AngleAxisd(turn, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
}

// The sharp features of the box turned by `turn` about the axis (1, 2, 3).
SurfaceFeatures turned_box_features(double turn) {
  TriSurface surface = box_surface();
  for (Vec3& p : surface.points) p = turning(turn) * p;
  return sharp_features(surface, feature_angle_degrees());
}

// The box turned by `turn` about the axis (1, 2, 3): its edges across the octree's.
HexdcResult box_mesh(bool crease_layer, double turn = 0.0) {
  const Eigen::Matrix3d r = turning(turn);
  HexdcOptions options;
  options.level = 4;
  options.source = "box.off";
  options.features = turned_box_features(turn);
  options.crease_layer = crease_layer;
  return hexdc_mesh(
      test_fields::sample_paper_cube([&](const Vec3& p) { return test_fields::box_distance(r.transpose() * p); }),
      [&](const Vec3& p) { return Vec3(r * test_fields::closest_on_box(r.transpose() * p)); }, options);
}

// Turned by half a radian: its edges run across the octree's.
constexpr double kTurn = 0.5;

TEST(FeatureLayer, TurnedBoxMeshesValidWithMoreCreasesOnHexEdges) {
  const HexdcResult plain = box_mesh(false, kTurn);
  const HexdcResult layered = box_mesh(true, kTurn);
  EXPECT_EQ(test_hexdc::invalid_hexes(layered.mesh), 0);
  EXPECT_GE(layered.improved.min_scaled_jacobian, 0.3);
  EXPECT_EQ(layered.capture.creases, 12);
  EXPECT_EQ(layered.feature_layer.chains.size(), 12U);
  // Measured without the layer too: the chains are found, the nodes stay where contouring put
  // them.
  EXPECT_EQ(plain.feature_layer.strip_hexes, 0);
  EXPECT_GT(layered.capture.captured, plain.capture.captured);
}

TEST(FeatureLayer, SameMeshForAnyThreadCount) {
  std::vector<HexMesh> meshes;
  for (const int threads : {1, 2}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    meshes.push_back(box_mesh(true, kTurn).mesh);
  }
  EXPECT_EQ(meshes[0].cells, meshes[1].cells);
  EXPECT_EQ(meshes[0].boundary_faces, meshes[1].boundary_faces);
  ASSERT_EQ(meshes[0].points.size(), meshes[1].points.size());
  for (std::size_t v = 0; v < meshes[0].points.size(); ++v)
    EXPECT_EQ(meshes[0].points[v], meshes[1].points[v]);  // bit for bit
}

// Of the box's side.
constexpr double kOnEdges = 1e-3;

TEST(FeatureLayer, BoxEdgesRunAlongHexEdgesAndItsCornersAreNodes) {
  const HexdcResult r = box_mesh(true);
  EXPECT_EQ(r.feature_layer.patches_pillowed, 6);
  EXPECT_EQ(test_hexdc::invalid_hexes(r.mesh), 0);
  EXPECT_GE(r.improved.min_scaled_jacobian, 0.3);
  EXPECT_EQ(r.capture.creases, 12);
  EXPECT_EQ(r.capture.captured, 12);
  const SurfaceFeatures features = sharp_features(box_surface(), feature_angle_degrees());
  const double side = 2.0 * kBoxHalfSide;
  for (const auto& crease : features.creases)
    EXPECT_LT(distance_to_boundary_edges(r.mesh, crease.front(), crease.back()), kOnEdges * side);
  for (const Vec3& corner : features.corners) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& quad : r.mesh.boundary_faces)
      for (const Index v : quad)
        nearest = std::min(nearest, (r.mesh.points[static_cast<std::size_t>(v)] - corner).norm());
    EXPECT_LT(nearest, kOnEdges * side);
  }
}

// Of the box's side: a pinned node on its feature, up to round-off.
constexpr double kOnFeature = 1e-9;

// The largest distance of `layer`'s chain nodes from their creases and of its corner nodes from
// their corners, relative to the box's side.
double farthest_pin(const HexMesh& mesh, const SurfaceFeatures& features, const FeatureLayer& layer) {
  double worst = 0.0;
  for (const FeatureChain& chain : layer.chains)
    for (const Index v : chain.nodes) {
      const Vec3& p = mesh.points[static_cast<std::size_t>(v)];
      const auto& crease = features.creases[static_cast<std::size_t>(chain.crease)];
      const Vec3 ab = crease.back() - crease.front();
      const double t = std::clamp((p - crease.front()).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      worst = std::max(worst, (p - (crease.front() + t * ab)).norm());
    }
  for (const PinnedNode& pin : layer.pinned)
    if (pin.corner) worst = std::max(worst, (mesh.points[static_cast<std::size_t>(pin.node)] - pin.target).norm());
  return worst / (2.0 * kBoxHalfSide);
}

TEST(FeaturePins, BoxChainsEndOnTheirCreasesAndCornersOnTheirCorners) {
  const HexdcResult r = box_mesh(true);
  EXPECT_EQ(test_hexdc::invalid_hexes(r.mesh), 0);
  EXPECT_EQ(r.optimisation.pinned_nodes, static_cast<Index>(r.feature_layer.pinned.size()));
  EXPECT_EQ(r.optimisation.pinned_off_features, 0);
  EXPECT_EQ(r.optimisation.features_released, 0);
  EXPECT_LT(farthest_pin(r.mesh, turned_box_features(0.0), r.feature_layer), kOnFeature);
  EXPECT_EQ(r.capture.captured, 12);
}

// Turned, some chain nodes start off their creases (the projection's guard held them back in
// the folded layer): the optimiser keeps every crease the projection captured.
TEST(FeaturePins, TurnedBoxKeepsTheCreasesTheProjectionCaptured) {
  const HexdcResult r = box_mesh(true, kTurn);
  EXPECT_EQ(test_hexdc::invalid_hexes(r.mesh), 0);
  EXPECT_GE(r.improved.min_scaled_jacobian, 0.3);
  EXPECT_EQ(r.optimisation.features_released, 0);
  EXPECT_LT(r.optimisation.pinned_off_features, r.projection.pinned_held_back);
  EXPECT_GE(r.capture.captured, r.capture_projected.captured);
}

// The box's layer following its creases, its pinned nodes projected onto them, then one hex at
// a chain node folded: its node opposite the chain node taken through the boundary.
struct FoldedBox {
  HexMesh mesh;
  SurfaceFeatures features = sharp_features(box_surface(), feature_angle_degrees());
  FeatureLayer layer = {};
};

FoldedBox folded_box() {
  FoldedBox box{box_hexes(4)};
  PillowOptions pillow;
  pillow.features = &box.features;
  pillow.follow_features = true;
  pillow_boundary(box.mesh, pillow, &box.layer);
  ProjectOptions project;
  project.pinned = &box.layer.pinned;
  project_boundary(box.mesh, test_fields::closest_on_box, project);
  const Index chain_node = box.layer.chains.front().nodes[1];
  for (const auto& cell : box.mesh.cells) {
    const auto at = std::find(cell.begin(), cell.end(), chain_node);
    if (at == cell.end()) continue;
    const auto c = static_cast<std::size_t>(at - cell.begin());
    // The hex corner opposite c (corners 0-3 around the bottom, 4-7 above them).
    const std::size_t opposite = (c + 2) % 4 + (c < 4 ? 4 : 0);
    Vec3& p = box.mesh.points[static_cast<std::size_t>(cell[opposite])];
    const Vec3& q = box.mesh.points[static_cast<std::size_t>(chain_node)];
    p = q + 1.5 * (q - p);
    break;
  }
  return box;
}

// The box's right angles below the optimiser's feature angle: its normals find no crease, only
// the pins keep the chain nodes on the edges.
constexpr double kBlindAngle = 100.0;

TEST(FeaturePins, AFoldBesideAChainIsUntangledWithThePinsKept) {
  FoldedBox box = folded_box();
  ASSERT_GT(test_hexdc::invalid_hexes(box.mesh), 0);
  OptimiseOptions options;
  options.feature_angle_deg = kBlindAngle;
  options.features = &box.features;
  options.feature_layer = &box.layer;
  const OptimiseStats stats = optimise_hexes(box.mesh, test_fields::closest_on_box, options);
  EXPECT_EQ(stats.features_released, 0);
  EXPECT_EQ(stats.pinned_off_features, 0);
  EXPECT_LT(farthest_pin(box.mesh, box.features, box.layer), kOnFeature);
  EXPECT_EQ(test_hexdc::invalid_hexes(box.mesh), 0);
}

// A domain without triangles has no creases to chain: the optimiser finds the box's edges and
// corners from the surface's normals as without the layer.
TEST(FeaturePins, NoPinnedNodeLeavesTheNormalsToFindTheFeatures) {
  HexMesh mesh = box_hexes(4);
  pillow_boundary(mesh);
  project_boundary(mesh, test_fields::closest_on_box);
  const SurfaceFeatures none;
  const FeatureLayer no_chains;
  OptimiseOptions options;
  options.features = &none;
  options.feature_layer = &no_chains;
  const OptimiseStats stats = optimise_hexes(mesh, test_fields::closest_on_box, options);
  EXPECT_EQ(stats.pinned_nodes, 0);
  EXPECT_EQ(stats.corner_nodes, 8);
  EXPECT_GT(stats.crease_nodes, 0);
}

}  // namespace
}  // namespace volmesh
