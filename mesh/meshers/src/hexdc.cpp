// The dual-contouring hex mesher (volmesh/hexdc/dual_contouring.hpp): the domain's signed
// distances on a (2^dim + 1)^3 grid, contoured at octree level --level, then given the buffer
// layer (pillow.hpp), smoothed (smoothing.hpp) and its boundary projected onto the domain's
// surface (project.hpp).
#include <algorithm>
#include <array>
#include <chrono>
#include <limits>
#include <sstream>

#include "hexdc_field.hpp"
#include "hexdc_surface.hpp"
#include "registration.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/domain/grid.hpp"
#include "volmesh/domain/grid_sdf.hpp"
#include "volmesh/hexdc/dual_contouring.hpp"
#include "volmesh/hexdc/hex_quality.hpp"
#include "volmesh/hexdc/pillow.hpp"
#include "volmesh/hexdc/project.hpp"
#include "volmesh/hexdc/smoothing.hpp"

namespace volmesh::meshers {

namespace {

using Clock = std::chrono::steady_clock;

// One node of margin around the domain needs 2^level >= 4 nodes per axis (hexdc_margin).
constexpr int kMinLevel = 2;
// The default grid has 2^2 voxels per node side: enough crossings for each boundary node's
// QEF to see the surface's curvature, at 64 samples per node.
constexpr int kDefaultVoxelsLog2 = 2;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// k of a signed-distance grid domain whose own samples are a cubic 2^k + 1 grid, else 0.
int own_depth(const Domain& domain) {
  const auto* sdf = dynamic_cast<const SdfGridDomain*>(&domain);
  if (sdf == nullptr) return 0;
  const auto& d = sdf->grid().dims;
  if (d[0] != d[1] || d[0] != d[2] || !is_octree_dim(d[0])) return 0;
  int k = 0;
  while ((Index{1} << k) + 1 < d[0]) ++k;
  return k;
}

struct HexFigures {
  double min_scaled_jacobian = std::numeric_limits<double>::infinity();
  double max_quad_distortion_deg = 0.0;
  Index invalid = 0;  // failing the ten corner tets
  Index first_invalid = -1;
  Vec3 first_invalid_centre = Vec3::Zero();
};

HexFigures hex_figures(const HexMesh& hexes) {
  HexFigures f;
  for (std::size_t c = 0; c < hexes.cells.size(); ++c) {
    std::array<Vec3, 8> corners;
    Vec3 centre = Vec3::Zero();
    for (int v = 0; v < 8; ++v) {
      corners[v] = hexes.points[hexes.cells[c][v]];
      centre += corners[v] / 8.0;
    }
    const HexQuality q = hex_quality(corners);
    f.min_scaled_jacobian = std::min(f.min_scaled_jacobian, q.scaled_jacobian);
    f.max_quad_distortion_deg = std::max(f.max_quad_distortion_deg, q.max_quad_distortion_deg);
    if (q.corner_tets_positive) continue;
    if (f.invalid++ == 0) {
      f.first_invalid = static_cast<Index>(c);
      f.first_invalid_centre = centre;
    }
  }
  return f;
}

MeshResult mesh_hexdc(const Domain& domain, const MeshRequest& request) {
  const int level = *request.level;
  if (level < kMinLevel)
    throw InputError("hexdc: --level " + std::to_string(level) + ": at least " +
                     std::to_string(kMinLevel) + " (one node of margin around the domain)");
  const int depth = static_cast<int>(given<std::int64_t>(request.options, "dim").value_or(
      own_depth(domain) > 0 ? own_depth(domain)
                            : std::min(level + kDefaultVoxelsLog2, kHexdcMaxDepth)));
  if (level > depth)
    throw InputError("hexdc: --level " + std::to_string(level) + " is deeper than --dim " +
                     std::to_string(depth) + " (at most --level " + std::to_string(depth) + ")");

  const Clock::time_point sampling = Clock::now();
  const VoxelGrid field = hexdc_field(domain, depth, hexdc_margin(level));
  const double field_seconds = seconds_since(sampling);

  const Clock::time_point contouring = Clock::now();
  HexdcStats stats;
  HexMesh hexes = to_hex_mesh(hexdc_uniform(field, level, &stats));
  const double contour_seconds = seconds_since(contouring);

  // The buffer layer takes every hex off the boundary but one face; smoothing then repairs
  // hexes it left failing, now that they are interior.
  const Clock::time_point improving = Clock::now();
  const PillowStats pillow = pillow_boundary(hexes);
  const SmoothingStats smoothing = smooth_hexes(hexes);
  const double improve_seconds = seconds_since(improving);

  // The paper's boundary refinement: boundary nodes onto the TRUE boundary, crease and corner
  // nodes onto their features.
  const Clock::time_point projecting = Clock::now();
  const ProjectStats projection = project_boundary(hexes, hexdc_surface(domain));
  const double project_seconds = seconds_since(projecting);

  // The ten corner tets are stricter than check_validity: a mesh failing them is refused.
  const HexFigures f = hex_figures(hexes);
  if (f.invalid > 0) {
    std::ostringstream where;
    where << "(" << f.first_invalid_centre.x() << ", " << f.first_invalid_centre.y() << ", "
          << f.first_invalid_centre.z() << ")";
    throw InputError("hexdc: " + std::to_string(f.invalid) + " of " +
                     std::to_string(hexes.num_cells()) + " hexes of " + request.domain_name +
                     " fail the ten corner tets, the first cell " +
                     std::to_string(f.first_invalid) + " at " + where.str());
  }
  MeshResult r;
  r.mesh = to_poly_mesh(hexes);
  r.h = field.spacing.x() * static_cast<double>(Index{1} << (depth - level));
  r.summary = {{"nodes_per_axis", stats.nodes_per_axis},
               {"samples_per_axis", field.dims[0]},
               {"interior_vertices", stats.interior_vertices},
               {"boundary_vertices", stats.boundary_vertices},
               {"qef_fallbacks", stats.qef_fallbacks},
               {"hexes", stats.hexes},
               {"invalid_before_pillow", stats.invalid_hexes},
               {"pillow_copies", pillow.boundary_nodes},
               {"pillow_hexes", pillow.pillow_hexes},
               {"pillow_shrunk_copies", pillow.shrunk_copies},
               {"two_boundary_faces_before_pillow", pillow.multi_boundary_hexes_before},
               {"two_boundary_faces_after_pillow", pillow.multi_boundary_hexes_after},
               {"invalid_after_pillow", pillow.invalid_hexes_after},
               {"min_scaled_jacobian_before_pillow", pillow.min_scaled_jacobian_before},
               {"min_scaled_jacobian_after_pillow", pillow.min_scaled_jacobian_after},
               {"smoothing_sweeps", smoothing.sweeps},
               {"smoothing_moves", smoothing.moves_accepted},
               {"invalid_by_corner_tets", f.invalid},
               {"min_scaled_jacobian", f.min_scaled_jacobian},
               {"max_quad_distortion_deg", f.max_quad_distortion_deg},
               {"field_seconds", field_seconds},
               {"contour_seconds", contour_seconds},
               {"improve_seconds", improve_seconds},
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
                 .max = kHexdcMaxDepth}},
    .default_domain = "builtin:ball",
    .default_space = "q1",
    .run = mesh_hexdc,
}};

}  // namespace

}  // namespace volmesh::meshers
