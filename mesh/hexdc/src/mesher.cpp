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

// The hexes whose nodes are optimised again after projection, boundary nodes on the surface: the
// least scaled Jacobian aimed at for every hex, as ProjectOptions' floor. Fewer hexes than
// untangle_hexes' default target leave the boundary nodes fewer moves to spend on the rest.
constexpr double kSurfaceUntangleTarget = 0.3;

// Where each stage starts, as a fraction of the run (rough shares of its time).
constexpr double kContourStart = 0.0;
constexpr double kRefineStart = 0.06;
constexpr double kPillowStart = 0.1;
constexpr double kSmoothStart = 0.13;
constexpr double kUntangleStart = 0.22;
constexpr double kProjectStart = 0.28;
constexpr double kSurfaceUntangleStart = 0.4;
constexpr double kOptimiseStart = 0.47;
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

  // The buffer layer takes every hex off the boundary but one face; smoothing then repairs
  // hexes it left failing, now that they are interior.
  report(options.progress, "buffer layer", kPillowStart);
  const Clock::time_point improving = Clock::now();
  r.pillow = pillow_boundary(r.mesh);
  report(options.progress, "smoothing", kSmoothStart);
  r.smoothing = smooth_hexes(r.mesh);
  report(options.progress, "untangling", kUntangleStart);
  r.untangling = untangle_hexes(r.mesh);
  r.improve_seconds = seconds_since(improving);

  // The paper's boundary refinement: boundary nodes onto the TRUE boundary, crease and corner
  // nodes onto their features.
  report(options.progress, "projection", kProjectStart);
  const Clock::time_point projecting = Clock::now();
  r.projection = project_boundary(r.mesh, surface);
  // Projection fixes the buffer hexes' outer quads where it put them: the worst hexes are
  // optimised again with the boundary nodes free to slide on the surface.
  report(options.progress, "untangling on the surface", kSurfaceUntangleStart);
  r.surface_untangling =
      untangle_hexes(r.mesh, {.target_quality = kSurfaceUntangleTarget}, surface);
  r.project_seconds = seconds_since(projecting);
  // What the local moves leave: every free node at once, untangled if a tet is still folded,
  // then the worst corners and boundary quad angles raised.
  report(options.progress, "optimisation", kOptimiseStart);
  OptimiseOptions optimise;
  optimise.progress = part_of(options.progress, kOptimiseStart, kCheckStart);
  r.optimisation = optimise_hexes(r.mesh, surface, optimise);

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
