// [mpirun -np P] volmesh solve poisson|elasticity --problem NAME (--mesh M | --method X
//   --domain D --level N) [--space S] [--exact EXPR --source EXPR --k K] [--solver B]
//   [--partition metis|octree] -o out.vtu|out.pvtu [--json] [--quiet] [PETSc options]
// One solve, written as a VTU (or a PVTU, one piece per rank) with the solution, its error
// where an exact solution is known, and the regions. Under mpirun: distributed.hpp, and with
// --partition octree mesh_pieces.hpp (every rank meshes and solves its piece).
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "mesher_cli.hpp"
#include "progress_line.hpp"
#include "solver_option.hpp"
#include "volmesh/runs/distributed.hpp"
#include "volmesh/runs/mesh_pieces.hpp"
#include "volmesh/runs/mesh_run.hpp"
#include "volmesh/runs/solve_run.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/meshers/registry.hpp"

namespace volmesh::cli {

namespace {

struct SolveOptions {
  std::string kind, mesh, method, domain, space, output, partition;
  int level = -1;
  meshers::MethodOptions given;
  bool json = false, quiet = false;
  ProblemSpec problem;
  SolverBackend solver = SolverBackend::automatic;
};

// The share of the progress bar that reading or meshing takes; the solve and the writing
// follow.
constexpr double kMeshShare = 0.5;
constexpr double kWriteStart = 0.95;

// The mesh and the domain its boundary data refer to.
struct Input {
  PolyMesh mesh;
  std::unique_ptr<Domain> domain;
  std::string domain_name;
  double h = 0.0;  // 0 for a mesh read from a file
  // The mesh is its own domain: its boundary points are on the true boundary already (a
  // projection along normals could leave a point at a sharp edge for another surface).
  bool own_boundary = false;
  std::string default_space;  // the mesher's (MesherInfo::default_space)
  double check_seconds = 0.0;  // of a mesh read from a file
  // Under mpirun, a partitioned PVTU's parts: each cell's rank. Empty: METIS partitions.
  std::vector<Index> cell_part;
  // Under mpirun with --partition octree: `mesh` is this rank's piece, `piece` its numbers.
  bool in_pieces = false;
  RankPiece piece;
};

// Refuses a mesh read from a file that is not valid; numbers[1]: the check's seconds.
void check_read(const SolveOptions& opt, const PolyMesh& mesh, std::vector<double>& numbers) {
  const Clock::time_point checking = Clock::now();
  const ValidityReport r = check_validity(mesh);
  numbers[1] = seconds_since(checking);
  if (!r.valid())
    throw InputError(opt.mesh + ": invalid mesh, not solved (" +
                     (r.problems.empty() ? std::string("see volmesh check") : r.problems.front()) +
                     ")");
}

// Rank 0 reads or meshes (distributed.hpp), or under mpirun every rank reads its piece of a
// partitioned PVTU; every rank opens the domain. All of it is the stage "mesh".
Input read_input(const SolveOptions& opt, const Progress& progress) {
  Input in;
  std::vector<double> numbers{0.0, 0.0};  // h, check seconds
  if (!opt.mesh.empty()) {
    report(progress, "reading " + opt.mesh, 0.0);
    const bool pieces =
        fem::distributed_run() && std::filesystem::path(opt.mesh).extension() == ".pvtu";
    if (pieces)
      in.mesh = read_pieces_on_ranks(opt.mesh, in.cell_part);
    else
      in.mesh = mesh_on_rank_zero(
          [&] {
            PolyMesh mesh = read_mesh(opt.mesh);
            check_read(opt, mesh, numbers);
            return mesh;
          },
          &numbers);
    fem::stage("mesh", [&] {
      // The ranks hold the same mesh: a check that fails fails alike on every rank.
      if (pieces) check_read(opt, in.mesh, numbers);
      in.domain = opt.domain.empty() ? mesh_as_domain(in.mesh, opt.mesh) : open_domain(opt.domain);
    });
    in.check_seconds = numbers[1];
    in.domain_name = opt.domain.empty() ? opt.mesh : domain_display_name(opt.domain);
    in.own_boundary = opt.domain.empty();
    return in;
  }
  const meshers::MesherInfo& method = meshers::find_mesher(opt.method);
  const std::string spec = opt.domain.empty() ? method.default_domain : opt.domain;
  in.domain_name = domain_display_name(spec);
  in.default_space = method.default_space;
  meshers::MeshRequest request = uniform_request(in.domain_name, opt.level, opt.given,
                                                 part_of(progress, 0.0, 1.0, "meshing: "));
  if (opt.level < 0) request.level.reset();
  if (partition_in_pieces(opt.partition, opt.method, opt.given, opt.output)) {
    report(progress, "meshing on " + std::to_string(fem::ranks()) + " ranks", 0.0);
    fem::stage("mesh", [&] { in.domain = open_domain(spec); });
    RankMesh m = mesh_on_every_rank(method, *in.domain, request);
    in.h = m.h;
    in.mesh = std::move(m.piece.mesh);
    in.piece = std::move(m.piece);
    in.in_pieces = true;
    return in;
  }
  in.mesh = mesh_on_rank_zero(
      [&] {
        in.domain = open_domain(spec);
        meshers::MeshResult m = meshers::mesh(method, *in.domain, request);
        numbers[0] = m.h;
        return std::move(m.mesh);
      },
      &numbers);
  in.h = numbers[0];
  fem::stage("mesh", [&] {
    if (!in.domain) in.domain = open_domain(spec);
  });
  return in;
}

// The stage seconds of a run; in a distributed run rank 0's (which add up to its total) and
// the largest over the ranks.
nlohmann::json seconds_json(const std::vector<std::pair<const char*, double>>& stages,
                            double total) {
  nlohmann::json out;
  for (const auto& [name, s] : stages) out[name] = s;
  out["total"] = total;
  return out;
}

int run_solve(const SolveOptions& opt) {
  const Clock::time_point start = Clock::now();
  require_problem_kind(opt.kind, opt.problem);

  if (opt.method.empty() && !opt.given.empty()) {
    const auto& [name, value] = *opt.given.begin();
    std::cerr << "volmesh solve: " << meshers::option_text(name, value)
              << " is a meshing option: it needs --method\n";
    return 2;
  }
  if (!opt.method.empty() && !options_apply("solve", meshers::find_mesher(opt.method), opt.given))
    return 2;
  const bool distributed = fem::distributed_run();
  if (distributed && opt.solver == SolverBackend::eigen)
    throw InputError("--solver eigen runs on one process: run without mpirun, or with the PETSc solver");
  if (distributed && opt.space == "fv")
    throw InputError("--space fv: finite volumes run on one process: run without mpirun");
  const bool rank_zero = fem::rank() == 0;
  ProgressLine progress_line("solve", opt.quiet || !rank_zero);
  const Progress progress = progress_line.progress();
  const Input in = read_input(opt, part_of(progress, 0.0, kMeshShare));
  const double mesh_seconds = seconds_since(start) - in.check_seconds;
  const Clock::time_point partitioning = Clock::now();
  const std::vector<Index> cell_rank = !distributed || in.in_pieces ? std::vector<Index>{}
                                       : !in.cell_part.empty()      ? in.cell_part
                                                                    : partition_for_ranks(in.mesh);
  const double partition_seconds = seconds_since(partitioning);
  SolveRequest request{.kind = opt.kind,
                       .problem = opt.problem,
                       .space = opt.space,
                       .default_space = in.default_space,
                       .own_boundary = in.own_boundary,
                       .solver = {opt.solver, distributed && !in.in_pieces ? &cell_rank : nullptr}};
  if (in.in_pieces) {
    request.solver.piece_points = &in.piece.global_points;
    request.solver.piece_owner = &in.piece.point_owner;
    request.tag_names = boundary_tags_over_ranks(in.mesh);
  }
  request.warn = [&](const std::string& warning) {
    if (!rank_zero) return;
    progress_line.clear();
    std::cerr << "warning: " << warning << "\n";
  };
  SolveRun run;
  // What the problem finds wrong with a mesh file (a region without material data, a
  // boundary tag without a condition, a cell the space refuses) names the file.
  try {
    run = solve_problem(request, *in.domain, in.mesh, part_of(progress, kMeshShare, kWriteStart));
  } catch (const InputError& e) {
    if (opt.mesh.empty()) throw;
    throw InputError(opt.mesh + ": " + e.what());
  }
  const SpaceChoice& space = run.space;
  const fem::LinearSolveReport& report = run.report;
  const std::optional<fem::ErrorNorms>& errors = run.errors;
  const Clock::time_point writing = Clock::now();
  progress_line("writing " + opt.output, kWriteStart);
  if (in.in_pieces)
    write_piece_solution(in.mesh, std::move(run.fields), in.piece, opt.output);
  else
    write_solution(in.mesh, run.fields, cell_rank, opt.output);
  const double write_seconds = seconds_since(writing);
  progress_line.clear();
  const std::vector<std::pair<const char*, double>> stages{
      {"mesh", mesh_seconds},
      {"check", in.check_seconds},
      {"partition", partition_seconds},
      {"setup", run.problem_seconds + report.setup_seconds},
      {"assembly", report.assembly_seconds},
      {"preconditioner", report.preconditioner_seconds},
      {"solve", report.solve_seconds},
      {"errors", report.errors_seconds + run.fields_seconds},
      {"write", write_seconds}};
  const double total = seconds_since(start);
  std::vector<std::pair<const char*, double>> stages_max = stages;
  for (auto& [name, s] : stages_max) s = fem::max_over_ranks(s);
  const double total_max = fem::max_over_ranks(total);
  if (!rank_zero) return 0;

  const std::int64_t cells = in.in_pieces ? in.piece.global_cell_count : in.mesh.num_cells();
  const std::int64_t points = in.in_pieces ? in.piece.global_point_count : in.mesh.num_points();
  if (opt.json) {
    nlohmann::json j = solve_summary(request, run, in.domain_name, in.mesh);
    j["cells"] = cells;
    j["points"] = points;
    j["output"] = opt.output;
    j["seconds"] = seconds_json(stages, total);
    if (distributed) {
      j["ranks"] = fem::ranks();
      j["partition"] = in.in_pieces ? "octree" : "metis";
      j["seconds_max"] = seconds_json(stages_max, total_max);
    }
    if (!opt.method.empty()) j["method"] = opt.method, j["h"] = in.h;
    if (opt.level >= 0) j["level"] = opt.level;
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << opt.output << ": " << opt.problem.label() << " on " << in.domain_name << ", "
            << cells << " cells, " << run.dofs << " DOFs (" << space.name() << "); "
            << report.method << ", " << report.iterations << " iterations, residual "
            << report.residual << "; " << total << " s\n";
  if (errors)
    std::cout << "errors: L2 " << errors->l2 << ", Linf " << errors->linf << ", H1 " << errors->h1
              << "\n";
  return 0;
}

}  // namespace

Command add_solve_command(CLI::App& root) {
  auto opt = std::make_shared<SolveOptions>();
  CLI::App* app = root.add_subcommand(
      "solve", "Solve Poisson or linear elasticity on a mesh, or on a domain meshed by a method");
  app->add_option("kind", opt->kind, "poisson or elasticity")
      ->required()
      ->check(CLI::IsMember({"poisson", "elasticity"}));
  CLI::Option* problem = app->add_option("--problem", opt->problem.name,
                                         "named problem (" + [] {
                                           std::string names;
                                           for (const std::string& n : fem::problem_names())
                                             names += (names.empty() ? "" : ", ") + n;
                                           return names;
                                         }() + ")");
  CLI::Option* exact = app->add_option("--exact", opt->problem.exact,
                                       "exact solution u(x, y, z), a muparser expression");
  CLI::Option* source = app->add_option(
      "--source", opt->problem.source, "source f(x, y, z); default −kΔu of --exact");
  app->add_option("--k", opt->problem.k, "conductivity of every region with --exact/--source")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  exact->excludes(problem);
  source->excludes(problem);
  CLI::Option* mesh = app->add_option(
      "--mesh", opt->mesh,
      "mesh to solve on (.vtu .pvtu .msh DIR.foam); under mpirun -np P a .pvtu of P pieces "
      "(volmesh partition --parts P) is read one piece per rank");
  CLI::Option* method = app->add_option("--method", opt->method,
                                        "mesh the domain: " + meshers::mesher_names())
                            ->check(CLI::IsMember(mesher_names()));
  CLI::Option* level = app->add_option("--level", opt->level, "octree depth, the same inside as at the boundary, as in a study (grid: 2^level "
                                          "cells per side; size methods: h = the octree cell edge "
                                          "at that level)")
                           ->check(CLI::Range(0, 20));
  app->add_option("--domain", opt->domain,
                  "domain (builtin:NAME, surface, image, .json; default: the method's, " +
                      default_domains() +
                      "); with --mesh: the true boundary the boundary data are evaluated on "
                      "(default: the mesh's own boundary)");
  add_mesher_options(*app, opt->given, false);
  app->add_option("--space", opt->space,
                  "p1, p2, q1, polyhedral, or fv (default: polyhedral for octree methods, p1 "
                  "for tets, q1 for hexes)");
  app->add_option("-o,--output", opt->output,
                  "output mesh with the solution (.vtu, or .pvtu: one piece per rank)")
      ->required()
      ->check(CLI::Validator(
          [](std::string& s) {
            const auto ext = std::filesystem::path(s).extension();
            return ext == ".vtu" || ext == ".pvtu" ? std::string() : "must end in .vtu or .pvtu";
          },
          "FILE.vtu|FILE.pvtu"));
  add_solver_option(*app, opt->solver);
  // A mesh read from a file is partitioned by its pieces or by METIS.
  add_partition_option(*app, opt->partition)->excludes(mesh);
  app->add_flag("--json", opt->json, "print one JSON object on stdout");
  add_quiet_flag(*app, opt->quiet);
  mesh->excludes(method);
  level->needs(method);
  app->footer(
      "Examples:\n"
      "  volmesh solve poisson --problem sine --method staircase --domain builtin:ball "
      "--level 4 -o ball.vtu\n"
      "  volmesh solve poisson --mesh part.vtu --exact \"sin(x)*exp(y*z)\" -o u.vtu --json\n"
      "  volmesh solve elasticity --problem elastic-patch --method grid --level 3 -o patch.vtu");
  app->callback([app, mesh, method, level, opt] {
    if (mesh->count() == 0 && method->count() == 0)
      throw CLI::ValidationError("--mesh or --method", "give a mesh (--mesh M) or a method "
                                                       "(--method X --domain D --level N)");
    // A surface method meshes the surface as given; every other one needs a level (a size
    // method meshes at the octree cell edge of that level).
    if (method->count() > 0 && level->count() == 0 &&
        meshers::find_mesher(opt->method).resolution != meshers::Resolution::surface)
      throw CLI::ValidationError("--method " + opt->method, "needs --level");
  });
  return {app, [opt] { return run_solve(*opt); }};
}

}  // namespace volmesh::cli
