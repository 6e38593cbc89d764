// tet-projection: the exact projection mesher (mesh/tet, projection.hpp) on a domain's
// triangulated surfaces, rounded back to doubles with every tet checked (rounding.hpp).
#include <string>
#include <vector>

#include "registration.hpp"
#include "tet_surfaces.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/improve/coarsen.hpp"
#include "volmesh/improve/improve.hpp"
#include "volmesh/improve/json.hpp"
#include "volmesh/tet/directions.hpp"
#include "volmesh/tet/projection.hpp"
#include "volmesh/tet/rounding.hpp"

namespace volmesh::meshers {

namespace {

const std::string kMethod = "tet-projection";
// The range of --surface-size (surfacing::mesh_interfaces refuses sizes too small for the
// domain's bounds).
constexpr double kMinSurfaceSize = 1e-9, kMaxSurfaceSize = 1e9;

tet::ProjectionOptions projection_options(const MethodOptions& options) {
  const std::string axis = given<std::string>(options, "axis").value_or("auto");
  if (axis == "auto") return {};
  return {.auto_axis = false,
          .axis = axis == "x" ? tet::Axis::x : axis == "y" ? tet::Axis::y : tet::Axis::z};
}

nlohmann::json summary_of(const tet::ProjectionStats& s, const tet::Rounding& rounding,
                          double check_seconds, double round_seconds) {
  nlohmann::json stages = {{"check", check_seconds}};
  for (const auto& [stage, seconds] : s.seconds) stages[stage] = seconds;
  stages["round"] = round_seconds;
  return {{"direction", tet::direction_name(s.axis, s.tilt)},
          {"surface_triangles", s.triangles},
          {"top", s.top},
          {"bot", s.bot},
          {"wall", s.wall},
          {"plane", {{"vertices", s.plane_vertices}, {"triangles", s.plane_triangles}}},
          {"prisms", s.prisms},
          {"degenerate_prisms", s.degenerate_prisms},
          {"tets", s.tets},
          {"steiner_points", {{"boundary", s.boundary_steiner}, {"interior", s.interior_steiner}}},
          {"enclosed_volume", {{"exact", s.enclosed_volume.get_str()},
                               {"value", s.enclosed_volume.get_d()}}},
          {"rounding", {{"moved_points", rounding.moved_points},
                        {"repaired_prisms", rounding.repaired_prisms},
                        {"repaired_tets", rounding.repaired_tets},
                        {"directions_tried", rounding.directions_tried}}},
          {"stage_seconds", stages}};
}

MeshResult mesh_tet_projection(const Domain& domain, const MeshRequest& request) {
  auto clock = Clock::now();
  report(request.progress, "checking the surfaces", 0.0);
  const std::vector<tet::ProjectionSurface> surfaces =
      triangulated_surfaces(domain, request.domain_name, kMethod,
                            given<double>(request.options, "surface-size"))
          .surfaces;
  require_no_intersections(surfaces, request.domain_name, kMethod);
  const double check_seconds = seconds_since(clock);
  // A prism too thin for doubles along one direction is not along another: with the axis
  // left to the method, a mesh that rounding cannot keep positive is made again along the
  // other directions (directions.hpp) in turn.
  const tet::ProjectionOptions asked = projection_options(request.options);
  std::vector<tet::ProjectionOptions> attempts{asked};
  tet::ProjectionMesh exact;
  tet::Rounding rounding;
  TetMesh tets;
  double round_seconds = 0.0;
  for (std::size_t attempt = 0; attempt < attempts.size(); ++attempt) {
    exact = tet::tetrahedralize_by_projection(surfaces, attempts[attempt],
                                              part_of(request.progress, 0.05, 0.9));
    if (attempt == 0 && asked.auto_axis) {
      // The first of them is the untilted axis just tried.
      const std::vector<tet::ProjectionOptions> others =
          tet::projection_directions(exact.stats.axis);
      attempts.insert(attempts.end(), others.begin() + 1, others.end());
    }
    clock = Clock::now();
    report(request.progress, "rounding to doubles", 0.9);
    rounding = {};
    try {
      tets = tet::round_to_doubles(exact, surfaces, rounding);
      round_seconds = seconds_since(clock);
      rounding.directions_tried = static_cast<Index>(attempt + 1);
      break;
    } catch (const InputError&) {
      if (attempt + 1 == attempts.size()) throw;
    }
  }
  const bool improve_asked = given<bool>(request.options, "improve").value_or(false);
  std::vector<improve::Slide> slides;
  if (improve_asked) slides = tet::surface_slides(exact, surfaces, tets);
  const std::vector<Index> renumber = tet::drop_unused_points(tets);
  nlohmann::json improvement;
  if (improve_asked) {
    improve::CoarsenOptions coarsen;
    for (std::size_t v = 0; v < slides.size(); ++v)
      if (renumber[v] != kNoIndex) slides[renumber[v]] = slides[v];
    slides.resize(tets.points.size());
    coarsen.slides = std::move(slides);
    coarsen.progress = part_of(request.progress, 0.9, 0.93);
    const improve::CoarsenStats c = improve::coarsen_tet_mesh(tets, coarsen);
    improve::ImproveOptions options;
    options.progress = part_of(request.progress, 0.93, 1.0);
    const improve::ImproveStats i = improve::improve_tet_mesh(tets, options);
    improvement = {{"coarsen", {{"tets", {c.tets_before, c.tets_after}},
                                {"points", {c.points_before, c.points_after}},
                                {"interior_contractions", c.interior},
                                {"boundary_contractions", c.boundary}}},
                   {"improve", improve::stats_json(i)}};
    improvement["improve"]["seconds"] = i.seconds;
  }
  drop_cavities(tets, surfaces);
  MeshResult r;
  r.mesh = to_poly_mesh(tets);
  const Box3 box = domain.bounds();
  // No size is asked for: the longest edge stands for h.
  double h = 0.0;
  for (const auto& t : tets.cells)
    for (const auto& [a, b] : kTetEdges)
      h = std::max(h, (tets.points[t[a]] - tets.points[t[b]]).norm());
  r.h = h > 0.0 ? h : box.size().maxCoeff();
  r.summary = summary_of(exact.stats, rounding, check_seconds, round_seconds);
  if (improve_asked) r.summary["improvement"] = improvement;
  return r;
}

const Registration registered{MesherInfo{
    .name = kMethod,
    .description = "tetrahedra filling triangulated surfaces by projection, exact (refused "
                   "where rounding to doubles flattens a tet)",
    .resolution = Resolution::surface,
    .octree = false,
    .options = {{.name = "axis",
                 .help = "projection axis (default auto: the one with the fewest vertical "
                         "triangles)",
                 .type = OptionSpec::Type::choice,
                 .choices = {"x", "y", "z", "auto"}},
                {.name = "improve",
                 .help = "coarsen the mesh by edge contraction (interior points, then surface "
                         "Steiner points within their input triangle or edge), then improve it",
                 .type = OptionSpec::Type::flag},
                {.name = "surface-size",
                 .help = "for a domain not made of triangles (analytic, domain file, SDF grid, "
                         "image): triangulate its surfaces at this edge first",
                 .type = OptionSpec::Type::real,
                 .min = kMinSurfaceSize,
                 .max = kMaxSurfaceSize}},
    .default_domain = "builtin:schoenhardt",
    .default_space = "p1",
    .run = mesh_tet_projection,
}};

}  // namespace

}  // namespace volmesh::meshers
