// The dual-contouring hex mesher (volmesh/hexdc/mesher.hpp) on any domain: its options, the
// domain's signed distances (hexdc_field.hpp) and its true boundary (hexdc_surface.hpp).
#include <algorithm>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "hexdc_field.hpp"
#include "hexdc_summary.hpp"
#include "hexdc_surface.hpp"
#include "registration.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/domain/grid.hpp"
#include "volmesh/domain/grid_sdf.hpp"
#include "volmesh/hexdc/features.hpp"
#include "volmesh/hexdc/mesher.hpp"

namespace volmesh::meshers {

namespace {

// One node of margin around the domain needs 2^level >= 4 nodes per axis (hexdc_margin).
constexpr int kMinLevel = 2;
// The default grid has 2^2 voxels per node side: enough crossings for each boundary node's
// QEF to see the surface's curvature, at 64 samples per node.
constexpr int kDefaultVoxelsLog2 = 2;
constexpr int kBoxNumbers = 6;
// The share of the run the signed distances take, before the mesher's stages.
constexpr double kFieldShare = 0.2;
// The thin parts' widths are read from runs of samples across a part under two cells wide:
// with one voxel per node a part one node wide and one two nodes wide look alike, so a field
// the mesher samples itself gets at least 2^1 voxels per node when the refinement is on.
constexpr int kThinVoxelsLog2 = 1;

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

Eigen::AlignedBox3d parse_box(const std::string& text) {
  const std::string error = "hexdc: --refine-box " + text +
                            ": not six numbers x0,y0,z0,x1,y1,z1 with x0 < x1, y0 < y1, z0 < z1";
  std::vector<double> v;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    std::size_t used = 0;
    try {
      v.push_back(std::stod(item, &used));
    } catch (const std::exception&) {
      throw InputError(error);
    }
    if (used != item.size()) throw InputError(error);
  }
  if (v.size() != kBoxNumbers) throw InputError(error);
  const Vec3 lo(v[0], v[1], v[2]), hi(v[3], v[4], v[5]);
  if (!(lo.array() < hi.array()).all()) throw InputError(error);
  return {lo, hi};
}

HexdcRefinement refinement_of(const MethodOptions& options) {
  HexdcRefinement r;
  r.boundary_layers = static_cast<int>(given<std::int64_t>(options, "refine-boundary").value_or(0));
  if (const auto box = given<std::string>(options, "refine-box")) r.box = parse_box(*box);
  return r;
}

ThinParts thin_parts_of(const MethodOptions& options) {
  const std::string mode = given<std::string>(options, "thin-parts").value_or("auto");
  if (mode == "on") return ThinParts::on;
  return mode == "off" ? ThinParts::off : ThinParts::automatic;
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
  const ThinParts thin_parts = thin_parts_of(request.options);
  const int field_depth = thin_parts != ThinParts::off && own == 0
                              ? std::min(std::max(depth, level + kThinVoxelsLog2), kHexdcMaxDepth)
                              : depth;
  HexdcOptions options;
  options.level = level;
  options.refinement = refinement_of(request.options);
  options.thin_parts = thin_parts;
  options.source = request.domain_name;
  options.progress = part_of(request.progress, kFieldShare, 1.0);
  if (const auto angle = given<double>(request.options, "feature-angle"))
    options.feature_angle_deg = *angle;
  options.crease_layer = given<bool>(request.options, "crease-layer").value_or(false);

  report(request.progress, "signed distances", 0.0);
  const Clock::time_point sampling = Clock::now();
  const std::shared_ptr<const SignedDistance> outer = outer_surface_distance(domain);
  const VoxelGrid field = hexdc_field(domain, field_depth, hexdc_margin(level), outer.get());
  const double field_seconds = seconds_since(sampling);
  // The creases and corners of a surface domain's outer surface; an analytic or sampled domain
  // has no triangles to find them on.
  if (const auto* surfaces = dynamic_cast<const SurfaceDomain*>(&domain); outer != nullptr)
    options.features = sharp_features(surfaces->surface(outermost_surface(*surfaces)),
                                      options.feature_angle_deg);

  const HexdcResult hexes = hexdc_mesh(field, hexdc_surface(domain, outer), options);
  MeshResult r;
  r.mesh = to_poly_mesh(hexes.mesh);
  r.h = field.spacing.x() * static_cast<double>(Index{1} << (field_depth - level));
  r.summary = hexdc_summary(hexes);
  r.summary["thin_refinement"]["dim_asked"] = depth;
  r.summary["thin_refinement"]["dim"] = field_depth;
  r.summary["samples_per_axis"] = field.dims[0];
  r.summary["voxel_size"] = field.spacing.x();
  r.summary["field_seconds"] = field_seconds;
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
                {.name = "thin-parts",
                 .help = "refine where the solid is under two cells wide or its surface turns "
                         "by more than 45 degrees across a hex, the mesh at most doubled: on, "
                         "off, or auto (default): only when the mesh without it is refused or "
                         "its worst scaled Jacobian is below 0.3, keeping the better",
                 .type = OptionSpec::Type::choice,
                 .choices = {"auto", "on", "off"}},
                {.name = "refine-boundary",
                 .help = "split the N layers of hexes nearest the surface into 27 each, with "
                         "Schneiders' transition templates around them (default 0: none)",
                 .type = OptionSpec::Type::integer,
                 .min = 0,
                 .max = kMaxRefineLayers},
                {.name = "feature-angle",
                 .help = "a bend of the surface sharper than this many degrees is a crease, "
                         "measured in --json (default " +
                         std::to_string(feature_angle_degrees()).substr(0, 4) + ", as cutcell's)",
                 .type = OptionSpec::Type::real,
                 .min = 1.0,
                 .max = 90.0},
                {.name = "crease-layer",
                 .help = "make the buffer layer follow the creases: each a chain of hex edges "
                         "kept on its crease through the optimisation, the faces between them "
                         "pillowed again (more creases on hex edges, twice the layer's hexes; "
                         "a fold the chains hold is refused)",
                 .type = OptionSpec::Type::flag},
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
