// volmesh check <mesh> [--surface S] [--json]: validity, quality, and the distance of the
// mesh boundary to a reference surface.
#include <CLI/CLI.hpp>
#include <iostream>

#include "commands.hpp"
#include "progress_line.hpp"
#include "reports.hpp"
#include "volmesh/core/boundary.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/quality/measurements.hpp"
#include "volmesh/quality/report.hpp"
#include "volmesh/quality/surface_distance.hpp"

namespace volmesh::cli {

namespace {

struct CheckOptions {
  std::string mesh, surface, quality_output;
  bool json = false, quiet = false;
};

// Where the steps start on the progress bar.
constexpr double kValidityStart = 0.1, kQualityStart = 0.2, kDistanceStart = 0.4;

// Relative accuracy of the reported Hausdorff distance, as a fraction of the diagonal.
constexpr double kHausdorffBound = 1e-6;

nlohmann::json surface_comparison(const PolyMesh& mesh, const ValidityReport& validity,
                                  const std::string& path, bool json, ProgressLine& progress) {
  progress("distance to " + path, kDistanceStart);
  TriSurface surface = read_surface(path);
  const SurfaceReport sr = check_surface(surface, path);
  const double diagonal = bounding_box(surface.points).diagonal();
  const HausdorffDistance d =
      hausdorff_distance(boundary_surface(mesh), surface, kHausdorffBound * diagonal);
  progress.clear();
  const double volume_error = (validity.total_volume - sr.volume) / sr.volume;
  if (!json) {
    std::cout << "against " << path << " (volume " << sr.volume << ", diagonal " << diagonal
              << "):\n"
              << "  volume error " << volume_error << " (relative)\n"
              << "  Hausdorff distance " << d.symmetric() / diagonal
              << " of the diagonal (mesh to surface " << d.from_a / diagonal
              << ", surface to mesh " << d.from_b / diagonal << ")\n";
  }
  return {{"file", path},
          {"surface_volume", sr.volume},
          {"diagonal", diagonal},
          {"volume_error", volume_error},
          {"hausdorff", d.symmetric()},
          {"hausdorff_relative", d.symmetric() / diagonal},
          {"hausdorff_mesh_to_surface", d.from_a},
          {"hausdorff_surface_to_mesh", d.from_b}};
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
                  "reference surface: report the volume error and the two-sided Hausdorff "
                  "distance of the mesh boundary, relative to the bounding-box diagonal");
  app->add_option("-o,--quality-vtu", opt->quality_output,
                  "write the mesh with one cell array per quality metric (.vtu)");
  app->add_flag("--json", opt->json, "print one JSON object on stdout");
  add_quiet_flag(*app, opt->quiet);
  return {app, [opt] { return run_check(*opt); }};
}

}  // namespace volmesh::cli
