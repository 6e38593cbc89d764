// volmesh study convergence --problem P (--method M | --methods a,b) --levels A..B
//   [--space S] [--domain D] [--tets] -o dir [--json]
// Meshes and solves each level, prints the table with pairwise rates and least-squares
// slopes, and writes dir/convergence.csv, dir/convergence.png and dir/summary.json.
#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>

#include "commands.hpp"
#include "study_run.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh::cli {

namespace {

struct StudyOptions {
  StudySpec spec;
  std::string levels, output;
  bool json = false;
};

int run_study_command(StudyOptions opt) {
  std::tie(opt.spec.first_level, opt.spec.last_level) = parse_levels(opt.levels);
  // Progress once the run is long enough to wonder about: a quick failure stays one line.
  const auto start = std::chrono::steady_clock::now();
  const StudyOutcome outcome = run_study(opt.spec, [start](const std::string& line) {
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(1))
      std::cerr << line << "\n";
  });
  write_study_outputs(opt.output, outcome);
  if (opt.json) {
    std::cout << study_summary(outcome).dump(2) << "\n";
    return 0;
  }
  std::cout << outcome.problem << " on " << outcome.domain << "\n";
  fem::print_convergence_table(std::cout, outcome.series);
  std::cout << "wrote " << opt.output << "/convergence.csv, convergence.png, summary.json ("
            << outcome.seconds << " s)\n";
  return 0;
}

}  // namespace

Command add_study_command(CLI::App& root) {
  auto opt = std::make_shared<StudyOptions>();
  CLI::App* study = root.add_subcommand("study", "Convergence studies");
  study->require_subcommand(1);
  CLI::App* app = study->add_subcommand(
      "convergence",
      "Mesh and solve a problem over a range of levels: errors, rates, CSV, log-log PNG");
  CLI::Option* problem = app->add_option("--problem", opt->spec.problem.name,
                                         "named problem with an exact solution (sine, "
                                         "sine-neumann, patch-linear, lame, elastic-patch)");
  CLI::Option* exact = app->add_option("--exact", opt->spec.problem.exact,
                                       "exact solution u(x, y, z), a muparser expression");
  CLI::Option* source = app->add_option("--source", opt->spec.problem.source,
                                        "source f(x, y, z); default −kΔu of --exact");
  app->add_option("--k", opt->spec.problem.k, "conductivity with --exact/--source")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  exact->excludes(problem);
  source->excludes(problem);
  CLI::Option* method = app->add_option_function<std::string>(
      "--method", [opt](const std::string& m) { opt->spec.methods = {m}; },
      "mesher: staircase, cutcell, grid");
  method->check(CLI::IsMember(study_methods()));
  CLI::Option* methods = app->add_option("--methods", opt->spec.methods,
                                         "several methods compared in one table and plot, "
                                         "e.g. staircase,cutcell")
                             ->delimiter(',')
                             ->check(CLI::IsMember(study_methods()));
  method->excludes(methods);
  app->add_option("--levels", opt->levels, "levels A..B (octree depth; grid: 2^level cells "
                                           "per side)")
      ->required();
  app->add_option("--domain", opt->spec.domain,
                  "domain (default builtin:ball; builtin:box for grid)");
  app->add_option("--space", opt->spec.space,
                  "p1, p2, q1, polyhedral, fv (default: polyhedral for octree methods, p1 for "
                  "tets, q1 for hexes)");
  app->add_flag("--tets", opt->spec.tets, "grid: the Kuhn split into tetrahedra");
  app->add_option("-o,--output", opt->output, "output directory")->required();
  app->add_flag("--json", opt->json, "print the summary as one JSON object on stdout");
  app->footer(
      "Examples:\n"
      "  volmesh study convergence --problem sine --methods staircase,cutcell --levels 3..6 "
      "-o ball-study\n"
      "  volmesh study convergence --problem sine --method grid --tets --space p2 --levels 1..4 "
      "-o p2-study");
  app->callback([app, method, methods] {
    if (method->count() == 0 && methods->count() == 0)
      throw CLI::RequiredError("--method or --methods");
  });
  return {study, [opt] { return run_study_command(*opt); }};
}

}  // namespace volmesh::cli
