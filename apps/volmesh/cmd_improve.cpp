// volmesh improve <tet mesh> -o <out> [--json] [--max-seconds S] [--surface S] [--threads T]:
// raises the worst dihedral angles of any tet mesh (mesh/improve), its boundary and interface
// triangles kept (or, with --surface, its boundary points inside the surface's triangles and
// on its edges free to slide there), its regions and tags kept.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string_view>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "progress_line.hpp"
#include "thread_limit.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/improve/improve.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh::cli {

namespace {

struct ImproveCliOptions {
  std::string input, output, surface;
  double max_seconds = std::numeric_limits<double>::infinity();
  int threads = 0;
  bool json = false, quiet = false;
};

// Where the steps start on the progress bar.
constexpr double kImproveStart = 0.1, kImproveEnd = 0.9;

std::string first_problem(const ValidityReport& r) {
  return r.problems.empty() ? std::string("see volmesh check") : r.problems.front();
}

// The input as a tet mesh, or one line saying why it is none.
TetMesh read_tet_mesh(const std::string& path) {
  const PolyMesh poly = read_mesh(path);
  const ValidityReport validity = check_validity(poly);
  if (!validity.valid()) throw InputError(path + ": invalid mesh (" + first_problem(validity) + ")");
  TetMesh mesh;
  try {
    mesh = to_tet_mesh(poly);
  } catch (const InputError& e) {
    // "mesh: cell N is not a tetrahedron (...)", said of the file.
    std::string what = e.what();
    constexpr std::string_view kPrefix = "mesh: ";
    if (what.starts_with(kPrefix)) what.erase(0, kPrefix.size());
    throw InputError(path + ": " + what);
  }
  improve::require_positive_tets(mesh, path);
  return mesh;
}

nlohmann::json to_json(const improve::QualitySummary& q) {
  return {{"tets", q.tets},
          {"points", q.points},
          {"min_dihedral_deg", q.min_dihedral_deg},
          {"max_dihedral_deg", q.max_dihedral_deg},
          {"tets_below_10_deg", q.below_10_degrees},
          {"max_radius_edge", q.max_radius_edge},
          {"min_sine", q.min_quality}};
}

nlohmann::json to_json(const improve::OperationCounts& o) {
  return {{"smoothed", o.smoothed},           {"slid", o.slid},
          {"flips_3_2", o.flips_3_2},         {"flips_4_4", o.flips_4_4},
          {"edge_removals", o.edge_removals}, {"flips_2_3", o.flips_2_3},
          {"face_removals", o.face_removals}, {"contractions", o.contractions},
          {"insertions", o.insertions}};
}

int run_improve(const ImproveCliOptions& opt) {
  const auto threads = limit_threads(opt.threads);
  require_writable_mesh_path(opt.output);
  const Clock::time_point start = Clock::now();
  ProgressLine progress("improve", opt.quiet);
  progress("reading " + opt.input, 0.0);
  TetMesh mesh = read_tet_mesh(opt.input);
  improve::ImproveOptions options;
  options.max_seconds = opt.max_seconds;
  if (!opt.surface.empty()) options.slides = improve::slides_on_surface(mesh, read_surface(opt.surface));
  options.progress = part_of(progress.progress(), kImproveStart, kImproveEnd);
  const improve::ImproveStats stats = improve::improve_tet_mesh(mesh, options);

  progress("checking", kImproveEnd);
  const PolyMesh out = to_poly_mesh(mesh);
  const ValidityReport validity = check_validity(out);
  if (!validity.valid())
    throw InputError(opt.input + ": the improved mesh fails the check (" + first_problem(validity) +
                     "), not written");
  progress("writing " + opt.output, kImproveEnd);
  write_mesh(out, opt.output);
  progress.clear();

  const double seconds = seconds_since(start);
  if (opt.json) {
    const nlohmann::json j{{"input", opt.input},
                           {"output", opt.output},
                           {"before", to_json(stats.before)},
                           {"after", to_json(stats.after)},
                           {"operations", to_json(stats.operations)},
                           {"passes", stats.passes},
                           {"timed_out", stats.timed_out},
                           {"improve_seconds", stats.seconds},
                           {"seconds", seconds}};
    std::cout << j.dump(2) << "\n";
  }
  std::cerr << "wrote " << opt.output << ": " << stats.after.tets << " tets (" << stats.before.tets
            << " before), min dihedral " << stats.before.min_dihedral_deg << "° → "
            << stats.after.min_dihedral_deg << "°, max " << stats.before.max_dihedral_deg << "° → "
            << stats.after.max_dihedral_deg << "°" << (stats.timed_out ? " (time limit)" : "")
            << "\n";
  return 0;
}

}  // namespace

Command add_improve_command(CLI::App& root) {
  auto opt = std::make_shared<ImproveCliOptions>();
  CLI::App* app = root.add_subcommand(
      "improve", "Raise the worst dihedral angles of a tet mesh, its boundary kept");
  app->add_option("mesh", opt->input, "tet mesh (.vtu .msh .mesh, TetGen .node/.ele)")->required();
  app->add_option("-o,--output", opt->output, "output mesh (.vtu .msh .mesh .inp DIR.foam)")
      ->required();
  app->add_option("--surface", opt->surface,
                  "the surface the boundary covers (.stl .off .obj .ply): boundary points inside "
                  "its triangles or on its edges may slide there (default: every boundary point "
                  "stays)");
  app->add_option("--max-seconds", opt->max_seconds, "start no pass after this wall time")
      ->check(CLI::PositiveNumber);
  app->add_option("--threads", opt->threads, "at most this many threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  app->add_flag("--json", opt->json, "print one JSON object on stdout");
  add_quiet_flag(*app, opt->quiet);
  app->footer(R"(Examples:
  volmesh improve elephant.1.ele -o elephant.vtu     a TetGen mesh, its boundary kept
  volmesh improve part.msh -o part.vtu --surface part.stl --json)");
  return {app, [opt] { return run_improve(*opt); }};
}

}  // namespace volmesh::cli
