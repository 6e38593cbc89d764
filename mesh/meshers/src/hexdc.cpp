// The dual-contouring hex mesher (volmesh/hexdc/dual_contouring.hpp): the domain's signed
// distances on a (2^dim + 1)^3 grid, contoured at octree level --level, refined locally where
// asked (refine.hpp), given the buffer layer (pillow.hpp), smoothed (smoothing.hpp, untangle.hpp),
// its boundary projected onto the domain's surface (project.hpp) and its worst hexes optimised
// again with the boundary nodes sliding on that surface (untangle.hpp).
#include <algorithm>
#include <memory>
#include <optional>
#include <sstream>

#include "hexdc_field.hpp"
#include "hexdc_refine.hpp"
#include "hexdc_surface.hpp"
#include "registration.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/domain/grid.hpp"
#include "volmesh/domain/grid_sdf.hpp"
#include "volmesh/hexdc/dual_contouring.hpp"
#include "volmesh/hexdc/hex_mesh_stats.hpp"
#include "volmesh/hexdc/pillow.hpp"
#include "volmesh/hexdc/project.hpp"
#include "volmesh/hexdc/smoothing.hpp"
#include "volmesh/hexdc/untangle.hpp"

namespace volmesh::meshers {

namespace {

// One node of margin around the domain needs 2^level >= 4 nodes per axis (hexdc_margin).
constexpr int kMinLevel = 2;
// The default grid has 2^2 voxels per node side: enough crossings for each boundary node's
// QEF to see the surface's curvature, at 64 samples per node.
constexpr int kDefaultVoxelsLog2 = 2;

// The hexes whose nodes are optimised again after projection, boundary nodes on the surface: the
// least scaled Jacobian aimed at for every hex, as ProjectOptions' floor. Fewer hexes than
// untangle_hexes' default target leave the boundary nodes fewer moves to spend on the rest.
constexpr double kSurfaceUntangleTarget = 0.3;

// k of a signed-distance grid domain whose own samples are a cubic 2^k + 1 grid, 0 for other
// domains. Throws InputError for a grid of another size when no --dim asks to resample it: the
// paper's octree levels need 2^k + 1 samples per axis.
int own_depth(const Domain& domain, const MeshRequest& request, bool resample) {
  const auto* sdf = dynamic_cast<const SdfGridDomain*>(&domain);
  if (sdf == nullptr) return 0;
  const auto& d = sdf->grid().dims;
  if (d[0] != d[1] || d[0] != d[2] || !is_octree_dim(d[0])) {
    if (resample) return 0;
    throw InputError(request.domain_name + ": " + std::to_string(d[0]) + "x" +
                     std::to_string(d[1]) + "x" + std::to_string(d[2]) +
                     " samples: hexdc needs a cubic grid of 2^k + 1 samples per axis (--dim k "
                     "resamples it)");
  }
  int k = 0;
  while ((Index{1} << k) + 1 < d[0]) ++k;
  return k;
}

// One column of the paper's Table 1: the mesh after a stage, and the stage's time.
nlohmann::json stage_row(const HexMeshStats& s, double seconds) {
  nlohmann::json valence = nlohmann::json::object();
  for (const auto& [hexes, nodes] : s.valence) valence[std::to_string(hexes)] = nodes;
  return {{"nodes", s.nodes},
          {"cells", s.cells},
          {"max_edge", s.max_edge},
          {"min_edge", s.min_edge},
          {"max_aspect_ratio", s.max_aspect_ratio},
          {"max_quad_distortion_deg", s.max_quad_distortion_deg},
          {"degenerate_hexes", s.degenerate},
          {"valence", valence},
          {"min_scaled_jacobian", s.min_scaled_jacobian},
          {"mean_scaled_jacobian", s.mean_scaled_jacobian},
          {"seconds", seconds}};
}

MeshResult mesh_hexdc(const Domain& domain, const MeshRequest& request) {
  const int level = *request.level;
  if (level < kMinLevel)
    throw InputError("hexdc: --level " + std::to_string(level) + ": at least " +
                     std::to_string(kMinLevel) + " (one node of margin around the domain)");
  const std::optional<std::int64_t> dim = given<std::int64_t>(request.options, "dim");
  const int own = own_depth(domain, request, dim.has_value());
  const int depth = static_cast<int>(
      dim.value_or(own > 0 ? own : std::min(level + kDefaultVoxelsLog2, kHexdcMaxDepth)));
  if (level > depth)
    throw InputError("hexdc: --level " + std::to_string(level) + " is deeper than the grid of " +
                     request.domain_name + " allows: " + std::to_string((Index{1} << depth) + 1) +
                     " samples per axis (k = " + std::to_string(depth) +
                     ") give at most --level " + std::to_string(depth));

  const HexdcRefinement refinement = hexdc_refinement(request.options);
  const auto progress = [&](const char* stage, double fraction) {
    if (request.progress) request.progress(stage, fraction);
  };

  progress("signed distances", 0.0);
  const Clock::time_point sampling = Clock::now();
  const std::shared_ptr<const SignedDistance> outer = outer_surface_distance(domain);
  const VoxelGrid field = hexdc_field(domain, depth, hexdc_margin(level), outer.get());
  const double field_seconds = seconds_since(sampling);
  if (std::none_of(field.values.begin(), field.values.end(), [](float v) { return v >= 0.0F; }))
    throw InputError(request.domain_name +
                     ": no sample of the signed distance is >= 0: nothing is inside");

  progress("dual contouring", 0.2);
  const Clock::time_point contouring = Clock::now();
  HexdcStats stats;
  HexMesh hexes = to_hex_mesh(hexdc_uniform(field, level, &stats));
  const double contour_seconds = seconds_since(contouring);
  const HexMeshStats uniform = hex_mesh_stats(hexes);

  progress("refinement", 0.3);
  const Clock::time_point refining = Clock::now();
  const RefineStats refined = refine_hexdc(hexes, refinement);
  const double refine_seconds = seconds_since(refining);
  const HexMeshStats after_refinement =
      refined.hexes_after != refined.hexes_before ? hex_mesh_stats(hexes) : HexMeshStats{};

  // The buffer layer takes every hex off the boundary but one face; smoothing then repairs
  // hexes it left failing, now that they are interior.
  progress("buffer layer", 0.35);
  const Clock::time_point improving = Clock::now();
  const PillowStats pillow = pillow_boundary(hexes);
  progress("smoothing", 0.4);
  const SmoothingStats smoothing = smooth_hexes(hexes);
  progress("untangling", 0.55);
  const UntangleStats untangling = untangle_hexes(hexes);
  const double improve_seconds = seconds_since(improving);

  // The paper's boundary refinement: boundary nodes onto the TRUE boundary, crease and corner
  // nodes onto their features.
  progress("projection", 0.65);
  const Clock::time_point projecting = Clock::now();
  const SurfaceProjector surface = hexdc_surface(domain, outer);
  const ProjectStats projection = project_boundary(hexes, surface);
  progress("untangling on the surface", 0.85);
  // Projection fixes the buffer hexes' outer quads where it put them: the worst hexes are
  // optimised again with the boundary nodes free to slide on the surface.
  const UntangleStats surface_untangling =
      untangle_hexes(hexes, {.target_quality = kSurfaceUntangleTarget}, surface);
  const double project_seconds = seconds_since(projecting);

  // The ten corner tets are stricter than check_validity: a mesh failing them is refused.
  progress("corner tets", 0.95);
  const HexMeshStats improved = hex_mesh_stats(hexes);
  if (improved.degenerate > 0) {
    const Vec3& c = improved.first_degenerate_centre;
    std::ostringstream where;
    where << "(" << c.x() << ", " << c.y() << ", " << c.z() << ")";
    throw InputError("hexdc: " + std::to_string(improved.degenerate) + " of " +
                     std::to_string(improved.cells) + " hexes of " + request.domain_name +
                     " fail the ten corner tets, the first cell " +
                     std::to_string(improved.first_degenerate) + " at " + where.str());
  }
  MeshResult r;
  r.mesh = to_poly_mesh(hexes);
  r.h = field.spacing.x() * static_cast<double>(Index{1} << (depth - level));
  r.summary = {{"nodes_per_axis", stats.nodes_per_axis},
               {"samples_per_axis", field.dims[0]},
               {"voxel_size", field.spacing.x()},
               {"field_seconds", field_seconds},
               {"interior_vertices", stats.interior_vertices},
               {"boundary_vertices", stats.boundary_vertices},
               {"qef_fallbacks", stats.qef_fallbacks},
               {"pillow",
                {{"copies", pillow.boundary_nodes},
                 {"hexes", pillow.pillow_hexes},
                 {"shrunk_copies", pillow.shrunk_copies},
                 {"two_boundary_faces_before", pillow.multi_boundary_hexes_before},
                 {"two_boundary_faces_after", pillow.multi_boundary_hexes_after},
                 {"degenerate_after", pillow.invalid_hexes_after}}},
               {"smoothing",
                {{"sweeps", smoothing.sweeps}, {"moves", smoothing.moves_accepted}}},
               {"untangling",
                {{"sweeps", untangling.sweeps},
                 {"moves", untangling.moves_accepted},
                 {"degenerate_before", untangling.invalid_hexes_before},
                 {"degenerate_after", untangling.invalid_hexes_after},
                 {"on_surface_sweeps", surface_untangling.sweeps},
                 {"on_surface_moves", surface_untangling.moves_accepted},
                 {"on_surface_features_released", surface_untangling.features_released},
                 {"on_surface_degenerate_after", surface_untangling.invalid_hexes_after}}},
               {"refinement", refinement_summary(refined)},
               {"projection",
                {{"nodes_projected", projection.projected},
                 {"nodes_kept_on_features", projection.feature_nodes},
                 {"nodes_held_back", projection.held_back},
                 {"max_distance_before", projection.max_distance_before},
                 {"max_distance_left", projection.max_distance_left},
                 {"max_feature_distance", projection.max_feature_distance},
                 {"min_scaled_jacobian_before", projection.min_scaled_jacobian_before},
                 {"min_scaled_jacobian_after", projection.min_scaled_jacobian_after},
                 {"seconds", project_seconds}}}};
  // The paper's Table 1 columns: uniform, refined (when asked), improved.
  nlohmann::json& stages = r.summary["stages"];
  stages["uniform"] = stage_row(uniform, contour_seconds);
  if (refined.hexes_after != refined.hexes_before)
    stages["refined"] = stage_row(after_refinement, refine_seconds);
  stages["improved"] = stage_row(improved, improve_seconds + project_seconds);
  return r;
}

const Registration registered{MesherInfo{
    .name = "hexdc",
    .description = "all-hex dual contouring of the domain's signed distances on a cubic grid",
    .resolution = Resolution::level,
    .octree = false,
    .options = {{.name = "dim",
                 .help = "grid depth k: 2^k + 1 samples per axis (default: a cubic 2^k + 1 "
                         "grid domain's own k, else min(level + 2, 10))",
                 .type = OptionSpec::Type::integer,
                 .min = 2,
                 .max = kHexdcMaxDepth},
                {.name = "refine-boundary",
                 .help = "split the N layers of hexes nearest the surface into 27 each, with "
                         "Schneiders' transition templates around them (default 0: none)",
                 .type = OptionSpec::Type::integer,
                 .min = 0,
                 .max = kMaxRefineLayers},
                {.name = "refine-box",
                 .help = "x0,y0,z0,x1,y1,z1: mark the nodes inside this box for refinement too "
                         "(hexes with every corner marked split into 27)",
                 .type = OptionSpec::Type::text}},
    .default_domain = "builtin:ball",
    .default_space = "q1",
    .run = mesh_hexdc,
}};

}  // namespace

}  // namespace volmesh::meshers
