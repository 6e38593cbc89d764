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

namespace {

// The steps every kind of problem takes: the space and the problem ("setup"), the solve, and
// the output fields ("errors"). `make_problem` builds the problem from the tags, `solve` and
// `fields` are the kind's solve_scalar/solve_vector and scalar_fields/vector_fields.
template <class MakeProblem, class Solve, class Fields>
SolveRun solve_kind(const SolveRequest& request, const PolyMesh& mesh, const Progress& progress,
                    MakeProblem make_problem, Solve solve, Fields fields) {
  SolveRun out;
  const std::vector<std::string>& tags =
      request.tag_names.empty() ? mesh.tag_names : request.tag_names;
  const Clock::time_point setting_up = Clock::now();
  decltype(make_problem(tags, out.warning)) problem;
  fem::stage("setup", [&] {
    out.space = choose_space(request.space, request.default_space, mesh);
    problem = make_problem(tags, out.warning);
  });
  if (request.own_boundary) problem.to_true_boundary = nullptr;
  if (!out.warning.empty() && request.warn) request.warn(out.warning);
  out.problem_seconds = seconds_since(setting_up);
  const auto s = solve(mesh, problem, out.space,
                       part_of(progress, 0.0, 1.0,
                               "solving " + request.kind + " (" + out.space.name() + "): "),
                       request.solver);
  out.dofs = s.dofs, out.report = s.solve, out.errors = s.errors;
  const Clock::time_point evaluating = Clock::now();
  fem::stage("errors", [&] { out.fields = fields(mesh, s, problem); });
  out.fields_seconds = seconds_since(evaluating);
  return out;
}

}  // namespace

SolveRun solve_problem(const SolveRequest& request, const Domain& domain, const PolyMesh& mesh,
                       const Progress& progress) {
  if (require_problem_kind(request.kind, request.problem) == fem::ProblemKind::elasticity)
    return solve_kind(
        request, mesh, progress,
        [&](const std::vector<std::string>& tags, std::string&) {
          return elasticity_problem(request.problem, domain, tags);
        },
        [](auto&&... a) { return solve_vector(a...); },
        [](auto&&... a) { return vector_fields(a...); });
  return solve_kind(
      request, mesh, progress,
      [&](const std::vector<std::string>& tags, std::string& warning) {
        return poisson_problem(request.problem, domain, tags, &warning);
      },
      [](auto&&... a) { return solve_scalar(a...); },
      [](auto&&... a) { return scalar_fields(a...); });
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
