#include "volmesh/runs/solve_run.hpp"

#include "volmesh/core/errors.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/fem/parallel.hpp"

namespace volmesh::cli {

namespace {

nlohmann::json errors_json(const std::optional<fem::ErrorNorms>& e) {
  if (!e) return nullptr;
  return {{"l2", e->l2}, {"linf", e->linf}, {"h1", e->h1}};
}

}  // namespace

fem::ProblemKind require_problem_kind(const std::string& kind, const ProblemSpec& problem) {
  const fem::ProblemKind found = problem_kind(problem);
  const bool elasticity = found == fem::ProblemKind::elasticity;
  if (elasticity != (kind == "elasticity"))
    throw InputError("problem " + problem.label() + " is " +
                     (elasticity ? "an elasticity" : "a Poisson") + " problem: use volmesh solve " +
                     (elasticity ? "elasticity" : "poisson"));
  return found;
}

SolveRun solve_problem(const SolveRequest& request, const Domain& domain, const PolyMesh& mesh,
                       const Progress& progress) {
  SolveRun out;
  const auto solving = [&] {
    return part_of(progress, 0.0, 1.0,
                   "solving " + request.kind + " (" + out.space.name() + "): ");
  };
  const std::vector<std::string>& tags =
      request.tag_names.empty() ? mesh.tag_names : request.tag_names;
  const Clock::time_point setting_up = Clock::now();
  if (require_problem_kind(request.kind, request.problem) == fem::ProblemKind::elasticity) {
    fem::ElasticityProblem problem;
    fem::stage("setup", [&] {
      out.space = choose_space(request.space, request.default_space, mesh);
      problem = elasticity_problem(request.problem, domain, tags);
    });
    if (request.own_boundary) problem.to_true_boundary = nullptr;
    out.problem_seconds = seconds_since(setting_up);
    const fem::VectorSolution s = solve_vector(mesh, problem, out.space, solving(), request.solver);
    out.dofs = s.dofs, out.report = s.solve, out.errors = s.errors;
    const Clock::time_point evaluating = Clock::now();
    fem::stage("errors", [&] { out.fields = vector_fields(mesh, s, problem); });
    out.fields_seconds = seconds_since(evaluating);
    return out;
  }
  fem::PoissonProblem problem;
  fem::stage("setup", [&] {
    out.space = choose_space(request.space, request.default_space, mesh);
    problem = poisson_problem(request.problem, domain, tags, &out.warning);
  });
  if (request.own_boundary) problem.to_true_boundary = nullptr;
  if (!out.warning.empty() && request.warn) request.warn(out.warning);
  out.problem_seconds = seconds_since(setting_up);
  const fem::ScalarSolution s = solve_scalar(mesh, problem, out.space, solving(), request.solver);
  out.dofs = s.dofs, out.report = s.solve, out.errors = s.errors;
  const Clock::time_point evaluating = Clock::now();
  fem::stage("errors", [&] { out.fields = scalar_fields(mesh, s, problem); });
  out.fields_seconds = seconds_since(evaluating);
  return out;
}

nlohmann::json solve_summary(const SolveRequest& request, const SolveRun& run,
                             const std::string& domain_name, const PolyMesh& mesh) {
  nlohmann::json j{{"problem", request.problem.label()},
                   {"kind", request.kind},
                   {"domain", domain_name},
                   {"space", run.space.name()},
                   {"cells", mesh.num_cells()},
                   {"points", mesh.num_points()},
                   {"dofs", run.dofs},
                   {"unknowns", run.report.unknowns},
                   {"linear_solver", run.report.method},
                   {"iterations", run.report.iterations},
                   {"residual", run.report.residual},
                   {"errors", errors_json(run.errors)}};
  if (!run.warning.empty()) j["warning"] = run.warning;
  return j;
}

}  // namespace volmesh::cli
