// volmesh improve <tet mesh> -o <out> [--json] [--max-seconds S] [--surface S] [--threads T]:
// raises the worst dihedral angles of any tet mesh (mesh/improve), its boundary and interface
// triangles kept (or, with --surface, its boundary points inside the surface's triangles and
// on its edges free to slide there), its regions and tags kept.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "progress_line.hpp"
#include "volmesh/runs/thread_limit.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/runs/improve_run.hpp"

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

int run_improve(const ImproveCliOptions& opt) {
  const auto threads = limit_threads(opt.threads);
  require_writable_mesh_path(opt.output);
  const Clock::time_point start = Clock::now();
  ProgressLine progress("improve", opt.quiet);
  progress("reading " + opt.input, 0.0);
  TetMesh mesh = tet_mesh_to_improve(read_mesh(opt.input), opt.input);
  const TriSurface surface = opt.surface.empty() ? TriSurface{} : read_surface(opt.surface);
  const Improved improved =
      improve_checked(std::move(mesh), surface, opt.max_seconds, opt.input,
                      part_of(progress.progress(), kImproveStart, kImproveEnd));
  const improve::ImproveStats& stats = improved.stats;
  progress("writing " + opt.output, kImproveEnd);
  write_mesh(improved.mesh, opt.output);
  progress.clear();

  const double seconds = seconds_since(start);
  if (opt.json) {
    nlohmann::json j = improve_summary(stats);
    j["input"] = opt.input;
    j["output"] = opt.output;
    j["seconds"] = seconds;
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
