// volmesh sdf <surface> --dim 2^k+1 -o <grid.rawiv> [--margin F] [--json] [--quiet]: exact
// signed distances (positive inside) on a cubic grid around the surface (a .rawiv domain).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "progress_line.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/domain/grid_sdf.hpp"
#include "volmesh/geometry/surface_check.hpp"
#include "volmesh/io/surface_io.hpp"
#include "volmesh/io/voxel_grid_io.hpp"
#include "volmesh/runs/mesh_input.hpp"

namespace volmesh::cli {

namespace {

struct SdfOptions {
  std::string surface, output;
  Index dim = 0;
  double margin = 0.05;
  bool json = false, quiet = false;
};

// The share of the progress bar that reading and checking the surface take; the sampling
// and the writing follow.
constexpr double kReadShare = 0.05;
constexpr double kWriteStart = 0.95;

int run_sdf(const SdfOptions& opt) {
  const Clock::time_point start = Clock::now();
  ProgressLine progress("sdf", opt.quiet);
  progress("reading " + opt.surface, 0.0);
  TriSurface surface = read_surface(opt.surface);
  // Refuses holes and the like with one line; flips an inward surface.
  const SurfaceReport report = check_surface(surface, opt.surface);
  progress.clear();
  for (const std::string& w : report.warnings) std::cerr << "warning: " << w << "\n";
  if (!report.self_intersections.empty())
    std::cerr << "warning: " << opt.surface
              << ": the sign of the distance may be wrong near the self-intersections\n";
  const double read_time = seconds_since(start);

  const Clock::time_point computing = Clock::now();
  const SignedDistance distance(std::move(surface), opt.surface);
  VoxelGrid grid = sdf_layout(distance.bounds(), opt.dim, opt.margin);
  const std::string stage = "distances at " + std::to_string(opt.dim) + "^3 points";
  distance.sample(grid, [&](double fraction) {
    progress(stage, kReadShare + fraction * (kWriteStart - kReadShare));
  });
  const double distance_time = seconds_since(computing);

  const Clock::time_point writing = Clock::now();
  progress("writing " + opt.output, kWriteStart);
  write_rawiv(grid, opt.output);
  const double write_time = seconds_since(writing);
  progress.clear();

  const auto [lo, hi] = std::minmax_element(grid.values.begin(), grid.values.end());
  const auto inside =
      std::count_if(grid.values.begin(), grid.values.end(), [](float v) { return v > 0.0f; });
  const double h = grid.spacing.x();
  if (opt.json) {
    const nlohmann::json j{{"surface", opt.surface},
                           {"output", opt.output},
                           {"triangles", report.triangles},
                           {"dims", grid.dims},
                           {"origin", {grid.origin.x(), grid.origin.y(), grid.origin.z()}},
                           {"spacing", h},
                           {"margin", opt.margin},
                           {"min_distance", *lo},
                           {"max_distance", *hi},
                           {"inside_samples", inside},
                           {"self_intersections", report.self_intersections.size()},
                           {"seconds",
                            {{"read_and_check", read_time},
                             {"distance", distance_time},
                             {"write", write_time},
                             {"total", seconds_since(start)}}}};
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << opt.output << ": " << opt.dim << "^3 signed distances, spacing " << h << ", from "
              << *lo << " to " << *hi << " (" << inside << " samples inside); distances "
              << distance_time << " s, total " << seconds_since(start) << " s\n";
  }
  return 0;
}

}  // namespace

Command add_sdf_command(CLI::App& root) {
  auto opt = std::make_shared<SdfOptions>();
  CLI::App* app = root.add_subcommand(
      "sdf", "Signed distances (positive inside) of a closed surface on a (2^k+1)^3 grid (.rawiv)");
  app->add_option("surface", opt->surface, "closed surface (.stl .off .obj .ply)")->required();
  app->add_option("--dim", opt->dim, "samples per axis: 2^k + 1, from 3 to 1025")
      ->required()
      ->check(CLI::Validator(
          [](std::string& s) {
            Index d = 0;
            const bool number = CLI::detail::lexical_cast(s, d);
            return number && d <= kMaxSdfDim && is_octree_dim(d) ? std::string()
                                                           : "must be 2^k + 1, from 3 to 1025";
          },
          "2^k+1"));
  app->add_option("-o,--output", opt->output, "output grid (.rawiv)")
      ->required()
      ->check(CLI::Validator(
          [](std::string& s) {
            std::string ext = std::filesystem::path(s).extension().string();
            std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
            return ext == ".rawiv" ? std::string() : "must end in .rawiv";
          },
          "FILE.rawiv"));
  app->add_option("--margin", opt->margin,
                  "space around the surface on each side, a fraction of the bounding box's "
                  "largest side")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  app->add_flag("--json", opt->json, "print one JSON object on stdout");
  add_quiet_flag(*app, opt->quiet);
  app->footer("Example: volmesh sdf armadillo.off --dim 129 -o armadillo.rawiv");
  return {app, [opt] { return run_sdf(*opt); }};
}

}  // namespace volmesh::cli
