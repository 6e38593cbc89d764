// tet-front: the advancing-front mesher (mesh/tet/front, front.hpp) on a domain's triangulated
// surfaces (triangulated at h first for a domain without triangles, remeshed to h on request),
// with its shape figures.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "registration.hpp"
#include "tet_surfaces.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/improve/json.hpp"
#include "volmesh/quality/histogram.hpp"
#include "volmesh/quality/tet_metrics.hpp"
#include "volmesh/surfacing/remesh.hpp"
#include "volmesh/tet_front/front.hpp"

namespace volmesh::meshers {

namespace {

const std::string kMethod = "tet-front";
// The min-dihedral histogram: 10° bins over [0°, 90°].
constexpr double kDihedralBinDegrees = 10.0;
constexpr int kDihedralBins = 9;
constexpr int kMinAuxRatio = 2, kMaxAuxRatio = 40;

// --interior's values, by FrontOptions::Interior.
std::string interior_name(tet::Interior interior) {
  return interior == tet::Interior::delaunay ? "delaunay" : "front";
}

nlohmann::json shape_of(const TetMesh& m) {
  std::vector<double> min_dihedral, max_dihedral, radius_edge;
  for (const auto& c : m.cells) {
    const TetMetrics q = tet_metrics(m.points[c[0]], m.points[c[1]], m.points[c[2]], m.points[c[3]]);
    min_dihedral.push_back(q.min_dihedral_deg);
    max_dihedral.push_back(q.max_dihedral_deg);
    radius_edge.push_back(q.radius_edge_ratio);
  }
  const MetricSummary low = summarize(
      "min_dihedral", min_dihedral,
      make_histogram(0.0, kDihedralBinDegrees * kDihedralBins, kDihedralBins));
  const MetricSummary high = summarize("max_dihedral", max_dihedral, make_histogram(0, 180, 1));
  const MetricSummary re = summarize("radius_edge", radius_edge, make_histogram(0, 1, 1));
  return {{"min_dihedral_deg", low.min},
          {"max_dihedral_deg", high.max},
          {"radius_edge", {{"max", re.max}, {"mean", re.mean}}},
          {"min_dihedral_histogram",
           {{"bin_deg", kDihedralBinDegrees}, {"counts", low.histogram.counts}}}};
}

// The improver's figures as `volmesh improve --json` names them.
nlohmann::json improve_json(const improve::ImproveStats& s) {
  nlohmann::json j = improve::stats_json(s);
  j["seconds"] = s.seconds;
  return j;
}

// Each surface remeshed to edge h (surfacing::remesh_isotropic); the figures over all of them.
nlohmann::json remesh(std::vector<tet::ProjectionSurface>& surfaces, double h) {
  long long sharp_edges = 0, before = 0;
  double to_input = 0.0, from_input = 0.0;
  for (tet::ProjectionSurface& p : surfaces) {
    surfacing::Remeshed r = surfacing::remesh_isotropic(p.surface, h);
    before += p.surface.num_triangles();
    sharp_edges += r.sharp_edges;
    to_input = std::max(to_input, r.hausdorff_to_input);
    from_input = std::max(from_input, r.hausdorff_from_input);
    p.surface = std::move(r.surface);
  }
  return {{"input_triangles", before},
          {"sharp_edges", sharp_edges},
          {"sharp_angle_deg", surfacing::kSharpAngleDegrees},
          {"hausdorff", {{"to_input", to_input}, {"from_input", from_input}}}};
}

// --interior-size's value, read as --size is (any number, nan and inf included, for the
// mesher to refuse by name); text that is no number is refused here.
double interior_size(const std::string& name, const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size())
    throw InputError("tet-front: " + name + ": --interior-size " + text + " is not a number");
  return value;
}

MeshResult mesh_tet_front(const Domain& domain, const MeshRequest& request) {
  auto clock = Clock::now();
  const double size = request.size.value_or(0.0);
  tet::FrontOptions options{.size = size};
  if (const auto n = given<std::int64_t>(request.options, "aux-ratio"))
    options.aux_ratio = static_cast<int>(*n);
  if (const auto k = given<std::int64_t>(request.options, "stop-after")) options.stop_after = *k;
  if (const auto i = given<std::string>(request.options, "interior"))
    options.interior = *i == interior_name(tet::Interior::delaunay) ? tet::Interior::delaunay
                                                                    : tet::Interior::front;
  // Before the boundary is triangulated at h: the domain's box holds the boundary's.
  const Box3 box = domain.bounds();
  tet::require_front_size(request.domain_name, size, options.aux_ratio, box.lo, box.hi);
  if (const auto interior = given<std::string>(request.options, "interior-size")) {
    options.interior_size = interior_size(request.domain_name, *interior);
    tet::require_front_interior_size(request.domain_name, options.interior_size, size, box.lo,
                                     box.hi);
  }
  report(request.progress, "triangulating the boundary", 0.0);
  BoundarySurfaces boundary = triangulated_surfaces(domain, request.domain_name, kMethod, size);
  std::vector<tet::ProjectionSurface>& surfaces = boundary.surfaces;
  const double surface_seconds = seconds_since(clock);
  double check_seconds = 0.0;
  const auto check = [&](const std::string& name) {
    const auto start = Clock::now();
    require_no_intersections(surfaces, name, kMethod);
    check_seconds += seconds_since(start);
  };
  report(request.progress, "checking the surfaces", 0.0);
  check(request.domain_name);
  nlohmann::json boundary_json = {{"triangulated", boundary.triangulated}};
  double remesh_seconds = 0.0;
  if (given<bool>(request.options, "remesh-surface").value_or(false)) {
    report(request.progress, "remeshing the boundary", 0.0);
    clock = Clock::now();
    boundary_json["remeshed"] = remesh(surfaces, size);
    remesh_seconds = seconds_since(clock);
    // Remeshing can fold a thin part of a clean input: said of the remeshed surface.
    std::ostringstream name;
    name << "the boundary of " << request.domain_name << " remeshed at --size " << size;
    check(name.str());
  }
  long long triangles = 0;
  for (const tet::ProjectionSurface& p : surfaces) triangles += p.surface.num_triangles();
  boundary_json["surfaces"] = surfaces.size();
  boundary_json["triangles"] = triangles;
  tet::FrontResult front =
      tet::tetrahedralize_by_front(surfaces, options, part_of(request.progress, 0.05, 1.0));
  drop_cavities(front.mesh, surfaces);
  const tet::FrontStats& s = front.stats;
  MeshResult r;
  r.mesh = to_poly_mesh(front.mesh);
  r.h = size;
  nlohmann::json stages = {
      {"surface", surface_seconds}, {"remesh", remesh_seconds}, {"check", check_seconds}};
  for (const auto& [stage, seconds] : s.seconds) stages[stage] = seconds;
  stages["improve"] = s.improve.seconds;
  r.summary = {{"tets", front.mesh.num_cells()},
               {"nodes", front.mesh.num_points()},
               {"aux_ratio", options.aux_ratio},
               {"size_field", {{"min", s.size_min},
                               {"max", s.size_max},
                               {"grading_rate", s.grading_rate}}},
               {"boundary", boundary_json},
               {"interior", {{"method", interior_name(options.interior)},
                             {"core_points", s.core_points},
                             {"core_tets", s.core_tets}}},
               {"front", {{"tets", s.front_tets},
                          {"new_nodes", s.new_nodes},
                          {"existing_node_tets", s.existing_node_tets},
                          {"relaxed_tets", s.relaxed_tets},
                          {"aux_points", s.aux_points},
                          {"aux_deleted", s.aux_deleted}}},
               {"fallback", {{"stalls", s.stalls},
                             {"cavity_faces", s.cavity_faces},
                             {"largest_cavity", s.largest_cavity},
                             {"tets", s.fallback_tets},
                             {"split_cavity_faces", s.split_cavity_faces},
                             {"refined_tets", s.refined_tets},
                             {"split_boundary_faces", s.split_boundary_faces},
                             {"steiner_points", s.steiner_points}}},
               {"improve", improve_json(s.improve)},
               {"shape", shape_of(front.mesh)},
               {"stage_seconds", stages}};
  return r;
}

const Registration registered{MesherInfo{
    .name = kMethod,
    .description = "tetrahedra of size h by advancing front, boundary triangles kept (stalls "
                   "closed by projection, else refused)",
    .resolution = Resolution::size,
    .octree = false,
    .options = {{.name = "aux-ratio",
                 .help = "auxiliary points at h / n (default " +
                         std::to_string(tet::kDefaultAuxRatio) + ")",
                 .type = OptionSpec::Type::integer,
                 .min = kMinAuxRatio,
                 .max = kMaxAuxRatio},
                {.name = "interior",
                 .help = "how each region's inside is filled: delaunay (the Delaunay tets of "
                         "a body-centred cubic lattice, the front only in the layer around "
                         "them) or front (the front throughout; default " +
                         interior_name(tet::FrontOptions{}.interior) + ")",
                 .type = OptionSpec::Type::choice,
                 .choices = {interior_name(tet::Interior::delaunay),
                             interior_name(tet::Interior::front)}},
                {.name = "interior-size",
                 .help = "graded sizes: grow the size inward from the boundary's past h up to H "
                         "(at least h, at most the bounding-box diagonal)",
                 .type = OptionSpec::Type::text},
                {.name = "remesh-surface",
                 .help = "remesh the boundary to edge h first (isotropic, sharp edges kept); "
                         "--json gives the Hausdorff distance to the input",
                 .type = OptionSpec::Type::flag},
                {.name = "stop-after",
                 .help = "testing: stop each region's front after N tets, as if it stalled, so "
                         "that the rest is closed by the fallback",
                 .type = OptionSpec::Type::integer,
                 .min = 0,
                 .max = 1e12}},
    .default_domain = "builtin:cube-inclusion",
    .default_space = "p1",
    .run = mesh_tet_front,
}};

}  // namespace

}  // namespace volmesh::meshers
