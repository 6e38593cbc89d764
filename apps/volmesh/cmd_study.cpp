// volmesh study convergence --problem P (--method M | --methods a,b) --levels A..B
//   [--space S] [--domain D] [method options, e.g. --tets] [--solver B] [--np P]
//   [--partition metis|octree] -o dir
//   [--json] [--quiet]
// Meshes and solves each level, prints the table with pairwise rates and least-squares
// slopes, and writes dir/convergence.csv, dir/convergence.png and dir/summary.json.
#include <CLI/CLI.hpp>
#include <iostream>

#include "commands.hpp"
#include "mesher_cli.hpp"
#include "progress_line.hpp"
#include "solver_option.hpp"
#include "volmesh/runs/distributed.hpp"
#include "volmesh/runs/study_run.hpp"
#include "volmesh/core/errors.hpp"

namespace volmesh::cli {

namespace {

struct StudyOptions {
  StudySpec spec;
  std::string levels, output;
  bool json = false, quiet = false;
  int np = 0;  // > 0: re-launch under mpirun with this many ranks
};

int run_study_command(StudyOptions opt) {
  if (opt.np > 0 && !fem::distributed_run()) return relaunch_under_mpirun(opt.np);
  for (const std::string& method : opt.spec.methods)
    if (!options_apply("study convergence", meshers::find_mesher(method), opt.spec.options))
      return 2;
  std::tie(opt.spec.first_level, opt.spec.last_level) = parse_levels(opt.levels);
  const bool rank_zero = fem::rank() == 0;
  ProgressLine progress("study", opt.quiet || !rank_zero);
  const StudyOutcome outcome = run_study(opt.spec, progress.progress());
  if (!rank_zero) return 0;
  progress("writing " + opt.output, 1.0);
  write_study_outputs(opt.output, outcome);
  progress.clear();
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
      "mesher: " + meshers::mesher_names());
  method->check(CLI::IsMember(mesher_names()));
  CLI::Option* methods = app->add_option("--methods", opt->spec.methods,
                                         "several methods compared in one table and plot, "
                                         "e.g. staircase,cutcell")
                             ->delimiter(',')
                             ->check(CLI::IsMember(mesher_names()));
  method->excludes(methods);
  app->add_option("--levels", opt->levels, "levels A..B (octree depth, the same inside as at "
                                           "the boundary; grid: 2^level cells per side; size "
                                           "methods: h = the octree cell edge at that level)")
      ->required();
  app->add_option("--domain", opt->spec.domain,
                  "domain (default: the method's, " + default_domains() + ")");
  app->add_option("--space", opt->spec.space,
                  "p1, p2, q1, polyhedral, fv (default: polyhedral for octree methods, p1 for "
                  "tets, q1 for hexes)");
  add_mesher_options(*app, opt->spec.options, false);
  app->add_option("-o,--output", opt->output, "output directory")->required();
  add_solver_option(*app, opt->spec.solver);
  add_partition_option(*app, opt->spec.partition);
  app->add_option("--np", opt->np,
                  "solve every level on P ranks: runs itself again under mpirun -np P")
      ->check(CLI::PositiveNumber);
  app->add_flag("--json", opt->json, "print the summary as one JSON object on stdout");
  add_quiet_flag(*app, opt->quiet);
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
