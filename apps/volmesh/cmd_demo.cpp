// volmesh demo [-o dir]: the main job on built-in data, end to end (`make demo`):
//   1. builtin:primitives meshed by the octree method (seven regions)
//   2. checked (validity must pass; region volumes against the exact ones)
//   3. exported to VTU and an OpenFOAM case and read back
//   4. partitioned into 4 parts with METIS
//   5. the multi-material Poisson problem solved on it, written as PVTU (one VTU per part)
//   6. the staircase-vs-cut-cell convergence study of the sine problem on builtin:ball:
//      table, CSV, log-log PNG, JSON
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>

#include "commands.hpp"
#include "progress_line.hpp"
#include "volmesh/runs/solve_setup.hpp"
#include "volmesh/runs/study_run.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/domain/builtin.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/open_domain.hpp"
#include "volmesh/io/partitioned_io.hpp"
#include "volmesh/meshers/registry.hpp"
#include "volmesh/partition/part_mesh.hpp"
#include "volmesh/partition/partition.hpp"

namespace volmesh::cli {

namespace {

namespace fs = std::filesystem;
// The pipeline's mesher and the methods the study compares.
const std::string kPipelineMethod = "cutcell";
const std::vector<std::string> kStudyMethods{"staircase", "cutcell"};
constexpr Index kParts = 4;
// A mesh read back has the volume it was written with, to the rounding of the sum.
constexpr double kRoundTripVolume = 1e-12;
// The study's verdict, as validation/geometry judges the meshers: the staircase's L∞ slope
// within kFirstOrder (first order, its volume error cancelling irregularly), the cut cells'
// L2 and L∞ slopes at least kSecondOrder.
constexpr double kFirstOrder[2] = {0.6, 1.4};
constexpr double kSecondOrder = 1.8;

struct DemoOptions {
  std::string output = "demo-output";
  int level = 6;                   // the primitives mesh
  std::string study_levels = "2..5";
  bool quiet = false;
};

void step(int n, const std::string& what) { std::cout << "\n[" << n << "/6] " << what << "\n"; }

std::string failure(const ValidityReport& r) {
  return r.problems.empty() ? std::string("see volmesh check") : r.problems.front();
}

void check_mesh(const PolyMesh& mesh) {
  const ValidityReport r = check_validity(mesh);
  if (!r.valid()) throw InputError("demo: the primitives mesh is invalid: " + failure(r));
  std::cout << "  valid: " << r.cells << " cells closed, positive volumes, region boundaries "
            << "closed; smallest cell volume " << r.min_cell_volume << "\n"
            << "  region      volume       exact   rel. error\n";
  const std::map<Index, double> exact = builtin_region_volumes("primitives");
  for (const auto& [region, volume] : r.region_volume) {
    const auto e = exact.find(region);
    std::cout << std::setw(8) << region << std::setw(12) << std::setprecision(6) << volume;
    if (e != exact.end())
      std::cout << std::setw(12) << e->second << std::setw(13) << std::setprecision(3)
                << (volume - e->second) / e->second;
    std::cout << "\n";
  }
}

// Written and read back: the same cells, points and volume, and still valid.
void round_trip(const PolyMesh& mesh, const fs::path& path) {
  write_mesh(mesh, path);
  const PolyMesh back = read_mesh(path);
  const ValidityReport a = check_validity(mesh), b = check_validity(back);
  const bool same = back.num_cells() == mesh.num_cells() &&
                    back.num_points() == mesh.num_points() && b.valid() &&
                    std::abs(b.total_volume - a.total_volume) <= kRoundTripVolume * a.total_volume;
  std::cout << "  " << path.string() << ": " << (same ? "read back identical" : "MISMATCH")
            << " (" << back.num_cells() << " cells, " << back.num_points() << " points)\n";
  if (!same) throw InputError("demo: " + path.string() + " does not read back as written");
}

// The values of a whole-mesh field at a part's points or cells.
Field restricted(const Field& f, const std::vector<Index>& global) {
  Field local{f.name, f.components, {}};
  for (Index g : global)
    for (int k = 0; k < f.components; ++k)
      local.values.push_back(f.values[static_cast<std::size_t>(g) * f.components + k]);
  return local;
}

// One VTU per part with the solution restricted to it.
std::vector<MeshPiece> solution_pieces(const PolyMesh& mesh, const Partition& partition,
                                       const MeshFields& fields) {
  std::vector<MeshPiece> pieces;
  Index p = 0;
  for (PartMesh& part : split_mesh(mesh, partition.cell_part, kParts)) {
    MeshPiece& piece = pieces.emplace_back();
    piece.fields.cell_ints.push_back({"partition", std::vector<Index>(part.mesh.num_cells(), p++)});
    piece.fields.cell_ints.push_back({"GlobalCellIds", part.global_cells});
    for (const Field& f : fields.point) piece.fields.point.push_back(restricted(f, part.global_points));
    for (const Field& f : fields.cell) piece.fields.cell.push_back(restricted(f, part.global_cells));
    piece.mesh = std::move(part.mesh);
  }
  return pieces;
}

void print_verdict(const StudyOutcome& outcome) {
  for (std::size_t m = 0; m < outcome.series.size(); ++m) {
    const fem::SeriesRates r = fem::convergence_rates(outcome.series[m]);
    const double l2 = r.slope[0], linf = r.slope[1];
    const bool staircase = outcome.methods[m] == "staircase";
    const bool as_expected = staircase ? linf >= kFirstOrder[0] && linf <= kFirstOrder[1]
                                       : l2 >= kSecondOrder && linf >= kSecondOrder;
    std::cout << "  " << outcome.series[m].label << ": L2 slope " << std::setprecision(3) << l2
              << ", Linf slope " << linf << " — expected ";
    if (staircase)
      std::cout << "first order (Linf slope in [" << kFirstOrder[0] << ", " << kFirstOrder[1] << "])";
    else
      std::cout << "second order (>= " << kSecondOrder << ")";
    std::cout << (as_expected ? ": yes" : ": NO") << "\n";
  }
}

int run_demo(const DemoOptions& opt) {
  const Clock::time_point start = Clock::now();
  const auto [first_level, last_level] = parse_levels(opt.study_levels);
  const fs::path out(opt.output);
  fs::create_directories(out);

  step(1, "mesh builtin:primitives (" + kPipelineMethod + ", level " +
              std::to_string(opt.level) + ")");
  Clock::time_point t = Clock::now();
  const std::unique_ptr<Domain> domain = open_domain("builtin:primitives");
  const meshers::MesherInfo& mesher = meshers::find_mesher(kPipelineMethod);
  const PolyMesh mesh = [&] {
    ProgressLine progress("demo", opt.quiet);
    meshers::MeshRequest request;
    request.domain_name = "builtin:primitives";
    request.level = opt.level;
    request.progress = part_of(progress.progress(), 0.0, 1.0, kPipelineMethod + ": ");
    return meshers::mesh(mesher, *domain, request).mesh;
  }();
  std::cout << "  " << mesh.num_cells() << " cells, " << mesh.num_points() << " points ("
            << seconds_since(t) << " s)\n";

  step(2, "check");
  check_mesh(mesh);

  step(3, "export and read back");
  round_trip(mesh, out / "primitives.vtu");
  round_trip(mesh, out / "primitives.foam");

  step(4, "partition into " + std::to_string(kParts) + " parts (METIS k-way)");
  t = Clock::now();
  PartitionOptions options;
  options.parts = kParts;
  const Partition partition = [&] {
    ProgressLine progress("demo", opt.quiet);
    progress("partitioning", 0.0);
    return partition_mesh(mesh, options, "primitives");
  }();
  const PartitionStats& s = partition.stats;
  std::cout << "  edge cut " << s.edge_cut << " faces, imbalance " << s.imbalance << ", cells per part";
  for (Index c : s.part_cells) std::cout << " " << c;
  std::cout << " (" << seconds_since(t) << " s)\n";

  step(5, "multi-material Poisson, k = region label, f = 1, u = 0 on the boundary");
  t = Clock::now();
  const ProblemSpec problem{"multi-material", "", "", 1.0};
  const fem::PoissonProblem poisson = poisson_problem(problem, *domain, mesh.tag_names);
  const SpaceChoice space = choose_space("", mesher.default_space, mesh);
  const fem::ScalarSolution solution = [&] {
    ProgressLine progress("demo", opt.quiet);
    return solve_scalar(mesh, poisson, space, part_of(progress.progress(), 0.0, 1.0, "solving: "));
  }();
  const std::vector<double>& u =
      solution.point_values.empty() ? solution.cell_values : solution.point_values;
  const auto [lo, hi] = std::minmax_element(u.begin(), u.end());
  std::cout << "  " << solution.dofs << " DOFs (" << space.name() << "), " << solution.solve.method
            << " " << solution.solve.iterations << " iterations, residual "
            << solution.solve.residual << "; u in [" << *lo << ", " << *hi << "] ("
            << seconds_since(t) << " s)\n";
  const fs::path pvtu = out / "primitives_solution.pvtu";
  write_pvtu(solution_pieces(mesh, partition, scalar_fields(mesh, solution, poisson)), pvtu);
  std::cout << "  wrote " << pvtu.string() << " (" << kParts << " pieces in "
            << (out / "primitives_solution").string() << "/)\n";

  step(6, "convergence on builtin:ball, problem sine, levels " + opt.study_levels);
  StudySpec spec;
  spec.problem.name = "sine";
  spec.methods = kStudyMethods;
  spec.domain = "builtin:ball";
  spec.first_level = first_level;
  spec.last_level = last_level;
  const StudyOutcome outcome = [&] {
    ProgressLine progress("demo", opt.quiet);
    return run_study(spec, part_of(progress.progress(), 0.0, 1.0, "study: "));
  }();
  write_study_outputs(out / "convergence", outcome);
  fem::print_convergence_table(std::cout, outcome.series);
  print_verdict(outcome);
  std::cout << "  wrote " << (out / "convergence").string()
            << "/convergence.csv, convergence.png, summary.json (" << outcome.seconds << " s)\n";

  std::cout << "\ndemo done in " << std::setprecision(3) << seconds_since(start) << " s; open "
            << pvtu.string() << " in ParaView, or run checkMesh -case "
            << (out / "primitives.foam").string() << "\n";
  return 0;
}

}  // namespace

Command add_demo_command(CLI::App& root) {
  auto opt = std::make_shared<DemoOptions>();
  CLI::App* app = root.add_subcommand(
      "demo", "The main job on built-in data: mesh, check, export, partition, solve, study");
  app->add_option("-o,--output", opt->output, "output directory")->capture_default_str();
  app->add_option("--level", opt->level, "octree level of the primitives mesh")
      ->check(CLI::Range(2, 9))
      ->capture_default_str();
  app->add_option("--study-levels", opt->study_levels, "levels A..B of the convergence study")
      ->capture_default_str();
  add_quiet_flag(*app, opt->quiet);
  app->footer(R"(Example: volmesh demo -o demo-output)");
  return {app, [opt] { return run_demo(*opt); }};
}

}  // namespace volmesh::cli
