// The refinement of thin and curved parts (refine_thin.hpp): a part one node wide is split within
// the growth bound, the mesh stays valid by the exact test and gets better, and the result does
// not depend on the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <oneapi/tbb/global_control.h>

#include "fields.hpp"
#include "hex_checks.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/hexdc/dual_contouring.hpp"
#include "volmesh/hexdc/mesher.hpp"
#include "volmesh/hexdc/refine_thin.hpp"

namespace volmesh {
namespace {

constexpr int kLevel = 4;  // nodes 0.125 apart on the paper's cube

// A ball with a square fin 0.16 thick sticking out of it along x: at level 4 the fin is one node
// layer across, every node of it on the surface.
constexpr double kBallRadius = 0.6;
const Vec3 kFinCentre(0.7, 0.0, 0.0), kFinHalf(0.25, 0.3, 0.08);

double finned_ball(const Vec3& p) {
  const Vec3 d = (p - kFinCentre).cwiseAbs() - kFinHalf;
  const double fin = -(d.cwiseMax(0.0).norm() + std::min(d.maxCoeff(), 0.0));
  return std::max(kBallRadius - p.norm(), fin);
}

// Newton steps along the field's gradient onto its zero set: close enough to the closest point
// for this surface.
Vec3 onto_finned_ball(const Vec3& p) {
  constexpr double kStep = 1e-6;
  constexpr int kSteps = 50;
  Vec3 x = p;
  for (int k = 0; k < kSteps; ++k) {
    Vec3 g;
    for (int a = 0; a < 3; ++a) {
      Vec3 e = Vec3::Zero();
      e[a] = kStep;
      g[a] = (finned_ball(x + e) - finned_ball(x - e)) / (2 * kStep);
    }
    if (g.squaredNorm() == 0.0) break;
    x -= finned_ball(x) * g / g.squaredNorm();
  }
  return x;
}

HexdcOptions options(ThinParts thin) {
  HexdcOptions o;
  o.level = kLevel;
  o.thin_parts = thin;
  o.source = "finned ball";
  return o;
}

HexMesh contoured(const VoxelGrid& field) { return to_hex_mesh(hexdc_uniform(field, kLevel, nullptr)); }

Index hexes_and_quads(const HexMesh& mesh) {
  return mesh.num_cells() + static_cast<Index>(mesh.boundary_faces.size());
}

// The fin's hexes are one hex across and thin by the field; some are refined, within the bound
// on hexes plus boundary quads (what the buffer layer turns into hexes).
TEST(HexdcThin, FinIsRefinedWithinTheBound) {
  const VoxelGrid field = test_fields::sample_paper_cube(finned_ball);
  HexMesh mesh = contoured(field);
  const Index before = hexes_and_quads(mesh);
  const ThinRefineStats stats = refine_thin_parts(mesh, field);
  EXPECT_GT(stats.thin_hexes, 0);
  EXPECT_GT(stats.thin_refined, 0);
  EXPECT_EQ(stats.hexes_before + stats.boundary_quads_before, before);
  EXPECT_EQ(stats.hexes_after, mesh.num_cells());
  EXPECT_EQ(stats.boundary_quads_after, static_cast<Index>(mesh.boundary_faces.size()));
  EXPECT_GT(mesh.num_cells(), stats.hexes_before);
  EXPECT_LE(hexes_and_quads(mesh), static_cast<Index>(kThinGrowth * static_cast<double>(before)));
}

// A tighter bound is kept as tightly: the budget counts the refined mesh exactly.
TEST(HexdcThin, TheGrowthBoundHolds) {
  const VoxelGrid field = test_fields::sample_paper_cube(finned_ball);
  for (const double growth : {1.4, 1.7}) {
    HexMesh mesh = contoured(field);
    const Index before = hexes_and_quads(mesh);
    const ThinRefineStats stats = refine_thin_parts(mesh, field, {}, growth);
    EXPECT_GT(stats.thin_refined, 0) << growth;
    EXPECT_LT(stats.thin_refined, stats.thin_hexes) << growth;
    EXPECT_LE(hexes_and_quads(mesh), static_cast<Index>(growth * static_cast<double>(before)))
        << growth;
  }
}

// Hexes with their centre within `radius` of p.
Index hexes_near(const HexMesh& mesh, const Vec3& p, double radius) {
  Index n = 0;
  for (std::size_t h = 0; h < mesh.cells.size(); ++h) {
    Vec3 centre = Vec3::Zero();
    for (const Vec3& c : test_hexdc::corners_of(mesh, h)) centre += c / 8.0;
    n += (centre - p).norm() < radius ? 1 : 0;
  }
  return n;
}

// Under a tight bound the seeds near the points given come first: the fin's far corner, which
// the narrowest-first order leaves out, is refined when asked for.
TEST(HexdcThin, SeedsNearThePointsGivenComeFirst) {
  constexpr double kGrowth = 1.4, kRadius = 0.15;
  const Vec3 far_corner = kFinCentre + Vec3(kFinHalf.x(), kFinHalf.y(), 0.0);
  const VoxelGrid field = test_fields::sample_paper_cube(finned_ball);
  HexMesh plain = contoured(field), asked = contoured(field);
  refine_thin_parts(plain, field, {}, kGrowth);
  refine_thin_parts(asked, field, {far_corner}, kGrowth);
  EXPECT_GT(hexes_near(asked, far_corner, kRadius), hexes_near(plain, far_corner, kRadius));
}

// The whole mesher with the refinement forced on: every hex passes the ten corner tets (exact),
// and the mesh has at most twice the hexes it has without.
TEST(HexdcThin, FinMeshesValidWithAtMostTwiceTheHexes) {
  const VoxelGrid field = test_fields::sample_paper_cube(finned_ball);
  const HexdcResult off = hexdc_mesh(field, onto_finned_ball, options(ThinParts::off));
  const HexdcResult on = hexdc_mesh(field, onto_finned_ball, options(ThinParts::on));
  EXPECT_GT(on.thin.thin_refined, 0);
  EXPECT_EQ(test_hexdc::invalid_hexes(on.mesh), 0);
  EXPECT_EQ(on.improved.degenerate, 0);
  EXPECT_GT(on.improved.min_scaled_jacobian, 0.0);
  EXPECT_GT(on.mesh.num_cells(), off.mesh.num_cells());
  EXPECT_LE(on.mesh.num_cells(), 2 * off.mesh.num_cells());
  EXPECT_EQ(off.thin.hexes_after, 0);  // not made
}

// The fin meshes well without the refinement (the optimiser opens its one-node-wide part), so
// the automatic choice keeps the mesh as it comes and makes no second one.
TEST(HexdcThin, AutomaticKeepsAGoodMeshAsItComes) {
  const VoxelGrid field = test_fields::sample_paper_cube(finned_ball);
  const HexdcResult off = hexdc_mesh(field, onto_finned_ball, options(ThinParts::off));
  const HexdcResult automatic = hexdc_mesh(field, onto_finned_ball, options(ThinParts::automatic));
  ASSERT_GE(off.improved.min_scaled_jacobian, 0.3);
  EXPECT_FALSE(automatic.thin_choice.tried);
  EXPECT_FALSE(automatic.thin_choice.kept);
  EXPECT_EQ(automatic.mesh.points, off.mesh.points);
  EXPECT_EQ(automatic.mesh.cells, off.mesh.cells);
}

// The measures run in parallel over the hexes; the marks are taken in one order, so the
// refined mesh is the same for any thread count.
TEST(HexdcThin, SameMeshForOneAndTwoThreads) {
  const VoxelGrid field = test_fields::sample_paper_cube(finned_ball);
  const auto refined = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                    static_cast<std::size_t>(threads));
    HexMesh mesh = contoured(field);
    refine_thin_parts(mesh, field);
    return mesh;
  };
  const HexMesh one = refined(1), two = refined(2);
  EXPECT_EQ(one.points, two.points);
  EXPECT_EQ(one.cells, two.cells);
  EXPECT_EQ(one.boundary_faces, two.boundary_faces);
}

}  // namespace
}  // namespace volmesh
