// volmesh check <mesh> [--surface S] [--json]: validity, quality, and the distance of the
// mesh boundary to a reference: a surface file, or an analytic domain's true surfaces.
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "progress_line.hpp"
#include "reports.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/quality/analytic_surfaces.hpp"
#include "volmesh/quality/measurements.hpp"
#include "volmesh/quality/report.hpp"

namespace volmesh::cli {

namespace {

struct CheckOptions {
  std::string mesh, surface, quality_output;
  bool json = false, quiet = false;
};

// Where the steps start on the progress bar.
constexpr double kValidityStart = 0.1, kQualityStart = 0.2, kDistanceStart = 0.4;

// Against a triangulated surface, the accuracy of the reported Hausdorff distance as a
// fraction of the diagonal.
constexpr double kHausdorffBound = 1e-6;
// Against an analytic domain, samples this many times finer than the mean cell size (the
// cell edge of a uniform octree mesh), as validation/geometry samples.
constexpr double kSamplesPerCell = 6.0;

// What the mesh is compared with: a surface file, or the true surfaces of an analytic domain.
struct Reference {
  std::unique_ptr<ReferenceSurface> surface;
  double volume = 0.0;  // 0 where not known
  double diagonal = 0.0;
  SurfaceDistanceOptions options;
};

Reference open_reference(const std::string& spec, const ValidityReport& validity) {
  Reference r;
  if (is_surface_file(spec)) {
    TriSurface surface = read_surface(spec);
    r.volume = check_surface(surface, spec).volume;
    r.diagonal = bounding_box(surface.points).diagonal();
    r.options = {.tolerance = kHausdorffBound * r.diagonal, .interfaces = false};
    r.surface = std::make_unique<TriangulatedSurface>(std::move(surface));
    return r;
  }
  const std::unique_ptr<Domain> domain = open_domain(spec);
  const auto* analytic = dynamic_cast<const AnalyticDomain*>(domain.get());
  if (!analytic)
    throw InputError(spec + ": not analytic: --surface takes a surface file (.stl .off .obj "
                            ".ply) or an analytic domain (builtin:ball, a .json of solids)");
  for (const auto& [region, volume] : exact_region_volumes(spec, *domain)) r.volume += volume;
  r.diagonal = domain->bounds().size().norm();
  const double cell = std::cbrt(std::abs(validity.total_volume) / static_cast<double>(validity.cells));
  if (!(cell > 0.0))
    throw InputError("--surface " + spec + ": the mesh has no volume to size the samples by");
  r.options = {.tolerance = cell / kSamplesPerCell, .interfaces = true};
  r.surface = std::make_unique<AnalyticSurfaces>(*analytic);
  return r;
}

nlohmann::json surface_comparison(const PolyMesh& mesh, const ValidityReport& validity,
                                  const std::string& spec, bool json, ProgressLine& progress) {
  progress("distance to " + spec, kDistanceStart);
  const Reference r = open_reference(spec, validity);
  const bool sampled = r.surface->triangulation() == nullptr;
  const TwoSidedDistance d = surface_distance(mesh, *r.surface, r.options).all;
  progress.clear();
  const double volume_error = (validity.total_volume - r.volume) / r.volume;
  if (!json) {
    std::cout << "against " << spec << " (";
    if (r.volume > 0.0) std::cout << "volume " << r.volume << ", ";
    std::cout << "diagonal " << r.diagonal << "):\n";
    if (r.volume > 0.0) std::cout << "  volume error " << volume_error << " (relative)\n";
    std::cout << "  Hausdorff distance " << d.hausdorff() / r.diagonal
              << " of the diagonal (mesh to surface " << d.mesh_to_surface.distance / r.diagonal
              << ", surface to mesh " << d.surface_to_mesh.distance / r.diagonal << ")";
    if (sampled) std::cout << ", samples " << r.options.tolerance << " apart";
    std::cout << "\n";
  }
  nlohmann::json j{{"file", spec},
                   {"diagonal", r.diagonal},
                   {"hausdorff", d.hausdorff()},
                   {"hausdorff_relative", d.hausdorff() / r.diagonal},
                   {"hausdorff_mesh_to_surface", d.mesh_to_surface.distance},
                   {"hausdorff_surface_to_mesh", d.surface_to_mesh.distance}};
  if (r.volume > 0.0) {
    j["surface_volume"] = r.volume;
    j["volume_error"] = volume_error;
  }
  if (sampled) j["sample_spacing"] = r.options.tolerance;
  return j;
}

int run_check(const CheckOptions& opt) {
  ProgressLine progress("check", opt.quiet);
  progress("reading " + opt.mesh, 0.0);
  const PolyMesh mesh = read_mesh(opt.mesh);
  progress("validity", kValidityStart);
  const ValidityReport validity = check_validity(mesh);
  progress.clear();
  nlohmann::json j{{"file", opt.mesh}, {"validity", to_json(validity)}};
  j["bounding_box"] = to_json(bounding_box(mesh.points));
  if (!opt.json) {
    std::cout << opt.mesh << "\n";
    print_validity(std::cout, validity);
  }
  // Geometry is meaningless when faces point at vertices or cells that do not exist.
  if (validity.bad_indices == 0) {
    progress("quality", kQualityStart);
    const QualityMeasurements measured = measure_quality(mesh);
    const QualityReport quality = quality_report(mesh, measured);
    progress.clear();
    j["quality"] = to_json(quality);
    if (!opt.json) print_quality(std::cout, quality);
    if (!opt.quality_output.empty()) {
      MeshFields fields;
      for (NamedArray& a : cell_quality_arrays(measured.cells))
        fields.cell.push_back({std::move(a.name), 1, std::move(a.values)});
      write_vtu(mesh, opt.quality_output, fields);
    }
  }
  if (!opt.surface.empty() && validity.bad_indices == 0)
    j["surface"] = surface_comparison(mesh, validity, opt.surface, opt.json, progress);
  if (opt.json) std::cout << j.dump(2) << "\n";
  if (!validity.valid()) {
    std::cerr << "volmesh: error: " << opt.mesh << ": invalid mesh"
              << (validity.problems.empty() ? "" : ": " + validity.problems.front()) << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

Command add_check_command(CLI::App& root) {
  auto opt = std::make_shared<CheckOptions>();
  CLI::App* app = root.add_subcommand("check", "Validity and quality report of a volume mesh");
  app->add_option("mesh", opt->mesh, "mesh (.vtu .msh)")->required();
  app->add_option("--surface", opt->surface,
                  "reference surface (.stl .off .obj .ply) or analytic domain (builtin:ball, "
                  "a .json of solids): report the volume error and the two-sided Hausdorff "
                  "distance of the mesh boundary, relative to the bounding-box diagonal");
  app->add_option("-o,--quality-vtu", opt->quality_output,
                  "write the mesh with one cell array per quality metric (.vtu)");
  app->add_flag("--json", opt->json, "print one JSON object on stdout");
  add_quiet_flag(*app, opt->quiet);
  app->footer(R"(Examples:
  volmesh check mesh.vtu                             validity and quality
  volmesh check case.foam --json                     the same as one JSON object on stdout
  volmesh check mesh.vtu --surface part.stl          + volume error and Hausdorff distance
  volmesh check ball.vtu --surface builtin:ball      against the true sphere)");
  return {app, [opt] { return run_check(*opt); }};
}

}  // namespace volmesh::cli
