#include "volmesh/hexdc/mesher.hpp"

#include <algorithm>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"

namespace volmesh {
namespace {

// Where each stage starts, as a fraction of the run (rough shares of its time).
constexpr double kContourStart = 0.0;
constexpr double kRefineStart = 0.06;
constexpr double kPillowStart = 0.1;
constexpr double kProjectStart = 0.15;
constexpr double kOptimiseStart = 0.3;
constexpr double kCheckStart = 0.97;

RefineStats refine_marked(HexMesh& mesh, const HexdcRefinement& refinement) {
  std::vector<char> marks = mark_boundary_layers(mesh, refinement.boundary_layers);
  if (refinement.box) {
    const std::vector<char> inside = mark_box(mesh, *refinement.box);
    for (std::size_t v = 0; v < marks.size(); ++v)
      marks[v] = static_cast<char>(marks[v] | inside[v]);
  }
  return refine_hexes(mesh, std::move(marks));
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
  HexdcResult r;

  report(options.progress, "dual contouring", kContourStart);
  const Clock::time_point contouring = Clock::now();
  r.mesh = to_hex_mesh(hexdc_uniform(field, options.level, &r.contouring));
  r.contour_seconds = seconds_since(contouring);
  r.uniform = hex_mesh_stats(r.mesh);

  report(options.progress, "refinement", kRefineStart);
  const Clock::time_point refining = Clock::now();
  r.refinement = refine_marked(r.mesh, options.refinement);
  r.refine_seconds = seconds_since(refining);
  if (r.refinement.hexes_after != r.refinement.hexes_before) r.refined = hex_mesh_stats(r.mesh);

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
  if (options.crease_layer) optimise.feature_angle_deg = 0.5 * options.feature_angle_deg;
  r.optimisation = optimise_hexes(r.mesh, surface, optimise);
  r.capture = crease_capture(r.mesh, options.features, r.feature_layer.chains);

  // The ten corner tets are stricter than check_validity: a mesh failing them is refused.
  report(options.progress, "corner tets", kCheckStart);
  r.improved = hex_mesh_stats(r.mesh);
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
