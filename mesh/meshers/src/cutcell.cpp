// The cut-cell octree method (MMCMS, volmesh/cutcell/cutcell.hpp).
#include "volmesh/meshers/cutcell_request.hpp"

#include <cmath>
#include <numbers>

#include "volmesh/meshers/octree_request.hpp"
#include "registration.hpp"

namespace volmesh::meshers {

namespace {

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }
double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

CutcellOptions cutcell_request(const MeshRequest& request) {
  CutcellOptions options;
  options.octree = octree_request(request);
  if (const auto points = given<std::string>(request.options, "interface-points"))
    options.interface_points =
        *points == "midpoint" ? InterfacePoints::midpoint : InterfacePoints::exact;
  if (const auto angle = given<double>(request.options, "feature-angle"))
    options.feature_theta = std::cos(radians(*angle));
  if (const auto levels = given<std::int64_t>(request.options, "crossing-levels"))
    options.crossing_levels = static_cast<int>(*levels);
  options.progress = request.progress;
  return options;
}

namespace {

MeshResult mesh_cutcell(const Domain& domain, const MeshRequest& request) {
  const CutcellOptions options = cutcell_request(request);
  CutcellStats stats;
  MeshResult r;
  r.mesh = cutcell_mesh(domain, options, &stats);
  r.h = octree_cell_size(domain, options.octree);
  r.summary = {{"leaves", stats.leaves},
               {"cut_cells", stats.cut_cells},
               {"max_leaf_level", stats.max_leaf_level},
               {"interface_points",
                options.interface_points == InterfacePoints::midpoint ? "midpoint" : "exact"},
               {"feature_angle", degrees(std::acos(options.feature_theta))},
               {"crossing_levels", options.crossing_levels},
               {"moved_vertices", stats.moved_vertices},
               {"split_edges", stats.split_edges},
               {"feature_points", stats.feature_points},
               {"min_cell_volume_ratio", stats.min_cell_volume_ratio},
               {"max_skewness", stats.max_skewness},
               {"max_non_orthogonality", stats.max_non_orthogonality},
               {"split_cells", stats.split_cells},
               {"merged_cells", stats.merged_cells},
               {"joined_faces", stats.joined_faces},
               {"bad_faces", stats.bad_faces},
               {"octree_seconds", stats.octree_seconds},
               {"cut_seconds", stats.cut_seconds}};
  return r;
}

const Registration registered{MesherInfo{
    .name = "cutcell",
    .description = "octree cut cells (MMCMS): polyhedra that follow boundaries and "
                   "interfaces, second order where they are smooth",
    .resolution = Resolution::level,
    .octree = true,
    .options = {{.name = "interface-points",
                 .help = "exact crossings (default) or edge midpoints (M3C as published)",
                 .type = OptionSpec::Type::choice,
                 .choices = {"exact", "midpoint"}},
                {.name = "feature-angle",
                 .help = "keep a bend of the surface sharper than this many degrees as a sharp "
                         "edge (default 25.8, the paper's cosine 0.9)",
                 .type = OptionSpec::Type::real,
                 .min = 1.0,
                 .max = 90.0},
                {.name = "crossing-levels",
                 .help = "levels below --level to which a leaf with an edge crossed by the "
                         "interfaces more than once is still split (default " +
                         std::to_string(CutcellOptions{}.crossing_levels) +
                         "; 0: the paper's meshes, fewer cut cells, faster, thin features "
                         "coarser)",
                 .type = OptionSpec::Type::integer,
                 .min = 0,
                 .max = 8}},
    .default_domain = "builtin:ball",
    .default_space = "polyhedral",
    .run = mesh_cutcell,
}};

}  // namespace

}  // namespace volmesh::meshers
