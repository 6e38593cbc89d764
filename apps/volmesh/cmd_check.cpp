// volmesh check <mesh> [--surface S] [--json]: validity, quality, and the distance of the
// mesh boundary to a reference: a surface file, or an analytic domain's true surfaces.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "progress_line.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/runs/check_run.hpp"
#include "volmesh/runs/reports.hpp"

namespace volmesh::cli {

namespace {

struct CheckOptions {
  std::string mesh, surface, quality_output;
  bool json = false, quiet = false;
};

void print_comparison(std::ostream& os, const SurfaceComparison& c) {
  const TwoSidedDistance& d = c.distance;
  os << "against " << c.name << " (";
  if (c.volume > 0.0) os << "volume " << c.volume << ", ";
  os << "diagonal " << c.diagonal << "):\n";
  if (c.volume > 0.0) os << "  volume error " << c.volume_error << " (relative)\n";
  os << "  Hausdorff distance " << d.hausdorff() / c.diagonal << " of the diagonal (mesh to surface "
     << d.mesh_to_surface.distance / c.diagonal << ", surface to mesh "
     << d.surface_to_mesh.distance / c.diagonal << ")";
  if (c.sample_spacing) os << ", samples " << *c.sample_spacing << " apart";
  os << "\n";
}

int run_check(const CheckOptions& opt) {
  ProgressLine progress("check", opt.quiet);
  progress("reading " + opt.mesh, 0.0);
  const PolyMesh mesh = read_mesh(opt.mesh);
  ReferenceOpener reference;
  if (!opt.surface.empty())
    reference = [&](const ValidityReport& validity) { return open_reference(opt.surface, validity); };
  const MeshCheck check = check_mesh(mesh, reference, progress.progress());
  progress.clear();
  if (opt.json) {
    std::cout << to_json(check, mesh, opt.mesh).dump(2) << "\n";
  } else {
    std::cout << opt.mesh << "\n";
    print_validity(std::cout, check.validity);
    if (check.quality) print_quality(std::cout, *check.quality);
    if (check.surface) print_comparison(std::cout, *check.surface);
  }
  if (check.measured && !opt.quality_output.empty()) {
    MeshFields fields;
    for (NamedArray& a : cell_quality_arrays(check.measured->cells))
      fields.cell.push_back({std::move(a.name), 1, std::move(a.values)});
    write_vtu(mesh, opt.quality_output, fields);
  }
  if (!check.validity.valid()) {
    std::cerr << "volmesh: error: " << opt.mesh << ": invalid mesh"
              << (check.validity.problems.empty() ? "" : ": " + check.validity.problems.front())
              << "\n";
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
