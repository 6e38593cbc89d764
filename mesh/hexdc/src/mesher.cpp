#include "volmesh/hexdc/mesher.hpp"

#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/hexdc/hex_quality.hpp"

namespace volmesh {
namespace {

// Where each stage starts, as a fraction of the run (rough shares of its time).
constexpr double kContourStart = 0.0;
constexpr double kRefineStart = 0.06;
constexpr double kPillowStart = 0.1;
constexpr double kProjectStart = 0.15;
constexpr double kOptimiseStart = 0.3;
constexpr double kCheckStart = 0.97;
// The target for every mesh's worst scaled Jacobian: a mesh below it, or refused, is
// made again with its thin parts refined (ThinParts::automatic).
constexpr double kThinRetryBelow = 0.3;
// Below every scaled Jacobian: what a refused mesh counts as when the two are compared.
constexpr double kRefusedWorst = -1.0;

RefineStats refine_marked(HexMesh& mesh, const HexdcRefinement& refinement) {
  std::vector<char> marks = mark_boundary_layers(mesh, refinement.boundary_layers);
  if (refinement.box) {
    const std::vector<char> inside = mark_box(mesh, *refinement.box);
    for (std::size_t v = 0; v < marks.size(); ++v)
      marks[v] = static_cast<char>(marks[v] | inside[v]);
  }
  return refine_hexes(mesh, std::move(marks));
}

// Every stage once, with or without the thin parts refined (those near `first` first); the ten
// corner tets not enforced.
HexdcResult mesh_stages(const VoxelGrid& field, const SurfaceProjector& surface,
                        const HexdcOptions& options, bool thin, const std::vector<Vec3>& first) {
  HexdcResult r;

  report(options.progress, "dual contouring", kContourStart);
  const Clock::time_point contouring = Clock::now();
  r.mesh = to_hex_mesh(hexdc_uniform(field, options.level, &r.contouring));
  r.contour_seconds = seconds_since(contouring);
  r.uniform = hex_mesh_stats(r.mesh);

  report(options.progress, "refinement", kRefineStart);
  const Clock::time_point refining = Clock::now();
  r.refinement = refine_marked(r.mesh, options.refinement);
  // Thin and curved parts, so that no part of the solid is one node across.
  if (thin) r.thin = refine_thin_parts(r.mesh, field, first);
  r.refine_seconds = seconds_since(refining);
  if (r.mesh.num_cells() != r.uniform.cells) r.refined = hex_mesh_stats(r.mesh);

  // The buffer layer takes every hex off the boundary but one face.
  report(options.progress, "buffer layer", kPillowStart);
  const Clock::time_point pillowing = Clock::now();
  PillowOptions pillow;
  if (!options.features.creases.empty() || !options.features.corners.empty())
    pillow.features = &options.features;
  pillow.follow_features = options.crease_layer;
  r.pillow = pillow_boundary(r.mesh, pillow, &r.feature_layer);
  r.pillow_seconds = seconds_since(pillowing);

  // The paper's boundary refinement: boundary nodes onto the TRUE boundary, crease and corner
  // nodes onto their features, as far as no valid hex folds.
  report(options.progress, "projection", kProjectStart);
  const Clock::time_point projecting = Clock::now();
  ProjectOptions project;
  if (options.crease_layer) project.pinned = &r.feature_layer.pinned;
  r.projection = project_boundary(r.mesh, surface, project);
  r.project_seconds = seconds_since(projecting);
  r.capture_projected = crease_capture(r.mesh, options.features, r.feature_layer.chains);
  // Every free node at once: untangled if a tet is folded, then the worst corners and boundary
  // quad angles raised, the boundary nodes sliding on the surface.
  report(options.progress, "optimisation", kOptimiseStart);
  OptimiseOptions optimise;
  optimise.progress = part_of(options.progress, kOptimiseStart, kCheckStart);
  // The layer's chain and corner nodes kept on their features to the end.
  if (options.crease_layer) {
    optimise.features = &options.features;
    optimise.feature_layer = &r.feature_layer;
  }
  r.optimisation = optimise_hexes(r.mesh, surface, optimise);
  r.capture = crease_capture(r.mesh, options.features, r.feature_layer.chains);

  report(options.progress, "corner tets", kCheckStart);
  r.improved = hex_mesh_stats(r.mesh);
  return r;
}

// A mesh's worst scaled Jacobian, kRefusedWorst when a hex fails the ten corner tets.
double worst(const HexdcResult& r) {
  return r.improved.degenerate > 0 ? kRefusedWorst : r.improved.min_scaled_jacobian;
}

// The centres of the hexes failing the ten corner tets.
std::vector<Vec3> failing_hex_centres(const HexMesh& mesh) {
  std::vector<Vec3> centres;
  for (const auto& cell : mesh.cells) {
    std::array<Vec3, 8> corners;
    Vec3 centre = Vec3::Zero();
    for (std::size_t c = 0; c < corners.size(); ++c) {
      corners[c] = mesh.points[static_cast<std::size_t>(cell[c])];
      centre += corners[c] / static_cast<double>(corners.size());
    }
    if (!hex_corner_tets_positive(corners)) centres.push_back(centre);
  }
  return centres;
}

// ThinParts::automatic: the mesh as it comes and, where a hex fails the ten corner tets or the
// worst scaled Jacobian is below kThinRetryBelow, once more with the thin parts refined; the
// better is kept.
HexdcResult mesh_choosing(const VoxelGrid& field, const SurfaceProjector& surface,
                          const HexdcOptions& options) {
  HexdcResult plain = mesh_stages(field, surface, options, false, {});
  if (worst(plain) >= kThinRetryBelow) return plain;
  HexdcOptions again = options;
  again.progress = part_of(options.progress, 0.0, 1.0, "thin parts refined: ");
  // A refused mesh has nothing to lose: the refinement starts where its hexes failed.
  const std::vector<Vec3> failing =
      worst(plain) == kRefusedWorst ? failing_hex_centres(plain.mesh) : std::vector<Vec3>{};
  HexdcResult refined = mesh_stages(field, surface, again, true, failing);
  const ThinChoice choice{.tried = true,
                          .kept = worst(refined) > worst(plain),
                          .min_scaled_jacobian_without = worst(plain),
                          .min_scaled_jacobian_with = worst(refined)};
  HexdcResult& kept = choice.kept ? refined : plain;
  if (!choice.kept) plain.thin = refined.thin;
  kept.thin_choice = choice;
  return std::move(kept);
}

}  // namespace

HexdcResult hexdc_mesh(const VoxelGrid& field, const SurfaceProjector& surface,
                       const HexdcOptions& options) {
  if (options.refinement.boundary_layers < 0 ||
      options.refinement.boundary_layers > kMaxRefineLayers)
    throw InputError("hexdc: boundary refinement of " +
                     std::to_string(options.refinement.boundary_layers) +
                     " layers outside [0, " + std::to_string(kMaxRefineLayers) + "]");
  if (std::none_of(field.values.begin(), field.values.end(), [](float v) { return v >= 0.0F; }))
    throw InputError(options.source +
                     ": no sample of the signed distance is >= 0: nothing is inside");
  HexdcResult r = options.thin_parts == ThinParts::automatic
                      ? mesh_choosing(field, surface, options)
                      : mesh_stages(field, surface, options, options.thin_parts == ThinParts::on, {});
  // The ten corner tets are stricter than check_validity: a mesh failing them is refused.
  if (r.improved.degenerate > 0) {
    const Vec3& c = r.improved.first_degenerate_centre;
    std::ostringstream where;
    where << "(" << c.x() << ", " << c.y() << ", " << c.z() << ")";
    throw InputError("hexdc: " + std::to_string(r.improved.degenerate) + " of " +
                     std::to_string(r.improved.cells) + " hexes of " + options.source +
                     " fail the ten corner tets, the first cell " +
                     std::to_string(r.improved.first_degenerate) + " at " + where.str());
  }
  return r;
}

}  // namespace volmesh
