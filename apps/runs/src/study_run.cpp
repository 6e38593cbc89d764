#include "volmesh/runs/study_run.hpp"

#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <fstream>
#include <string_view>

#include "volmesh/runs/distributed.hpp"
#include "volmesh/runs/mesh_pieces.hpp"
#include "volmesh/runs/mesh_run.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/io/open_domain.hpp"

namespace volmesh::cli {

namespace fs = std::filesystem;

namespace {

// Through a temporary name in the same directory, renamed at the end: a failed write leaves
// no partial file.
void write_file_atomically(const fs::path& path, const char* data, std::size_t size) {
  const fs::path temporary =
      path.parent_path() / ("." + path.filename().string() + ".tmp" + std::to_string(::getpid()));
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path.string() + ": cannot open for writing");
    out.write(data, static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(temporary, ec);
      throw InputError(path.string() + ": cannot write");
    }
  }
  std::error_code ec;
  fs::rename(temporary, path, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw InputError(path.string() + ": cannot write (" + ec.message() + ")");
  }
}

// The method with the options given to it: "grid tets", "cutcell interface-points midpoint".
std::string series_name(const std::string& method, const meshers::MethodOptions& options) {
  std::string name = method;
  for (const auto& [option, value] : options)
    name += " " + meshers::option_text(option, value).substr(std::string_view("--").size());
  return name;
}

// The problem's set-up is the stage "setup" (fem::stage), the solve's own stages follow.
// `tag_names`: the mesh's boundary tags (over all ranks for a mesh in pieces).
fem::LevelSolve solve_level(const StudySpec& spec, fem::ProblemKind kind, const Domain& domain,
                            const PolyMesh& mesh, const std::vector<std::string>& tag_names,
                            const SpaceChoice& space, const Progress& progress,
                            const Solver& solver) {
  fem::LevelSolve out;
  if (kind == fem::ProblemKind::elasticity) {
    fem::ElasticityProblem problem;
    fem::stage("setup", [&] { problem = elasticity_problem(spec.problem, domain, tag_names); });
    const fem::VectorSolution s = solve_vector(mesh, problem, space, progress, solver);
    out.dofs = s.dofs, out.solve = s.solve, out.errors = s.errors;
  } else {
    fem::PoissonProblem problem;
    fem::stage("setup", [&] { problem = poisson_problem(spec.problem, domain, tag_names); });
    const fem::ScalarSolution s = solve_scalar(mesh, problem, space, progress, solver);
    out.dofs = s.dofs, out.solve = s.solve, out.errors = s.errors;
  }
  return out;
}

nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; }

}  // namespace

std::pair<int, int> parse_levels(const std::string& text) {
  const auto number = [&](std::string_view digits, int& value) {
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    return ec == std::errc() && end == digits.data() + digits.size() && !digits.empty() &&
           digits.front() != '-' && digits.front() != '+';
  };
  const std::string_view t(text);
  const std::size_t dots = t.find("..");
  int first = 0, last = 0;
  const bool ok = dots == std::string_view::npos
                      ? number(t, first) && number(t, last)
                      : number(t.substr(0, dots), first) && number(t.substr(dots + 2), last);
  if (!ok) throw InputError("--levels " + text + ": expected A..B, e.g. 2..5");
  if (first > last) throw InputError("--levels " + text + ": the first level exceeds the last");
  return {first, last};
}

StudyOutcome run_study(const StudySpec& spec, const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  if (spec.first_level > spec.last_level)
    throw InputError("levels " + std::to_string(spec.first_level) + ".." +
                     std::to_string(spec.last_level) + ": the first level exceeds the last");
  const fem::ProblemKind kind = problem_kind(spec.problem);
  if (spec.problem.user() && spec.problem.exact.empty())
    throw InputError("--source without --exact: a study needs the exact solution");
  std::vector<const meshers::MesherInfo*> methods;
  for (const std::string& name : spec.methods) {
    methods.push_back(&meshers::find_mesher(name));
    meshers::check_options(*methods.back(), spec.options);
  }
  const std::string domain_spec =
      spec.domain.empty() ? methods.front()->default_domain : spec.domain;
  const std::unique_ptr<Domain> domain = open_domain(domain_spec);
  StudyOutcome outcome;
  outcome.problem = spec.problem.label();
  outcome.domain = domain_display_name(domain_spec);
  for (std::size_t m = 0; m < methods.size(); ++m) {
    const meshers::MesherInfo& method = *methods[m];
    const std::string name = series_name(method.name, spec.options);
    // The space follows from the first level's mesh; every level has the same cell kinds.
    std::optional<SpaceChoice> space;
    // Under mpirun with --partition octree, each level is meshed in pieces: this rank's.
    const bool in_pieces = partition_in_pieces(spec.partition, method.name, spec.options, "");
    RankPiece piece;
    const fem::MeshAtLevel mesh = [&](int level, const Progress& meshing) {
      const meshers::MeshRequest request =
          uniform_request(outcome.domain, level, spec.options, meshing);
      if (in_pieces) {
        RankMesh r = mesh_on_every_rank(method, *domain, request);
        piece = std::move(r.piece);
        fem::stage("setup", [&] {
          if (!space) space = choose_space(spec.space, method.default_space, piece.mesh);
        });
        return fem::StudyMesh{std::move(piece.mesh), r.h, piece.global_cell_count};
      }
      std::vector<double> h{0.0};
      PolyMesh m = mesh_on_rank_zero(
          [&] {
            meshers::MeshResult r = meshers::mesh(method, *domain, request);
            h[0] = r.h;
            return std::move(r.mesh);
          },
          &h);
      fem::stage("setup", [&] {
        if (!space) space = choose_space(spec.space, method.default_space, m);
      });
      return fem::StudyMesh{std::move(m), h[0]};
    };
    const fem::SolveOnMesh solve = [&](const PolyMesh& m, const Progress& solving) {
      if (in_pieces)
        return solve_level(spec, kind, *domain, m, boundary_tags_over_ranks(m), *space, solving,
                           {spec.solver, nullptr, &piece.global_points, &piece.point_owner});
      // A distributed run partitions every level into one part per rank.
      const std::vector<Index> cell_rank =
          fem::distributed_run() ? partition_for_ranks(m) : std::vector<Index>{};
      return solve_level(spec, kind, *domain, m, m.tag_names, *space, solving,
                         {spec.solver, fem::distributed_run() ? &cell_rank : nullptr});
    };
    const double share = 1.0 / static_cast<double>(methods.size());
    fem::ConvergenceSeries s = fem::run_convergence_study(
        method.name, spec.first_level, spec.last_level, mesh, solve,
        part_of(progress, m * share, (m + 1) * share, name + " "));
    // The label names the space, known once the first mesh exists.
    s.label = name + " (" + space->name() + ")";
    outcome.methods.push_back(method.name);
    outcome.spaces.push_back(space->name());
    outcome.series.push_back(std::move(s));
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

plot::LogLogChart study_chart(const StudyOutcome& outcome) {
  plot::LogLogChart chart;
  chart.title = outcome.problem + " on " + outcome.domain + ": error against h";
  chart.x_label = "h (cell edge)";
  chart.y_label = "error";
  chart.reference_slopes = {1.0, 2.0};
  const bool several = outcome.series.size() > 1;
  for (std::size_t m = 0; m < outcome.series.size(); ++m) {
    const fem::ConvergenceSeries& s = outcome.series[m];
    for (std::size_t k = 0; k < fem::kNorms.size(); ++k) {
      plot::Series line;
      line.label = (several ? s.label + " " : std::string()) + fem::norm_name(fem::kNorms[k]);
      bool any = false;
      for (const fem::LevelResult& r : s.levels) {
        line.x.push_back(r.h);
        line.y.push_back(fem::norm_value(r.errors, fem::kNorms[k]));
        any = any || std::isfinite(line.y.back());
      }
      if (!any) continue;  // e.g. no H1 error without the exact gradient
      line.colour = static_cast<int>(several ? m : k);
      line.marker = static_cast<int>(k);
      chart.series.push_back(std::move(line));
    }
  }
  return chart;
}

nlohmann::json study_summary(const StudyOutcome& outcome) {
  nlohmann::json series = nlohmann::json::array();
  for (std::size_t m = 0; m < outcome.series.size(); ++m) {
    const fem::ConvergenceSeries& s = outcome.series[m];
    const fem::SeriesRates rates = fem::convergence_rates(s);
    nlohmann::json levels = nlohmann::json::array(), slopes, pairwise;
    for (const fem::LevelResult& r : s.levels)
      levels.push_back({{"level", r.level},
                        {"h", r.h},
                        {"cells", r.cells},
                        {"dofs", r.dofs},
                        {"l2", finite_or_null(r.errors.l2)},
                        {"linf", finite_or_null(r.errors.linf)},
                        {"h1", finite_or_null(r.errors.h1)},
                        {"linear_solver", r.solve.method},
                        {"iterations", r.solve.iterations},
                        {"residual", r.solve.residual},
                        {"seconds",
                         {{"mesh", r.mesh_seconds},
                          {"setup", r.solve.setup_seconds},
                          {"assembly", r.solve.assembly_seconds},
                          {"preconditioner", r.solve.preconditioner_seconds},
                          {"solve", r.solve.solve_seconds},
                          {"errors", r.solve.errors_seconds},
                          {"total", r.seconds}}}});
    for (std::size_t k = 0; k < fem::kNorms.size(); ++k) {
      const std::string name = fem::norm_name(fem::kNorms[k]);
      slopes[name] = finite_or_null(rates.slope[k]);
      pairwise[name] = nlohmann::json::array();
      for (double r : rates.pairwise[k]) pairwise[name].push_back(finite_or_null(r));
    }
    series.push_back({{"label", s.label},
                      {"method", outcome.methods[m]},
                      {"space", outcome.spaces[m]},
                      {"levels", levels},
                      {"slope", slopes},
                      {"pairwise_rates", pairwise}});
  }
  return {{"problem", outcome.problem},
          {"domain", outcome.domain},
          {"series", series},
          {"seconds", outcome.seconds}};
}

void write_study_outputs(const fs::path& dir, const StudyOutcome& outcome) {
  // Everything is made before the first byte is written.
  const std::string csv = fem::convergence_csv(outcome.series);
  const std::vector<std::uint8_t> png = plot::render_loglog_png(study_chart(outcome));
  const std::string json = study_summary(outcome).dump(2) + "\n";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError(dir.string() + ": cannot create the output directory");
  write_file_atomically(dir / "convergence.csv", csv.data(), csv.size());
  write_file_atomically(dir / "convergence.png", reinterpret_cast<const char*>(png.data()),
                        png.size());
  write_file_atomically(dir / "summary.json", json.data(), json.size());
}

}  // namespace volmesh::cli
