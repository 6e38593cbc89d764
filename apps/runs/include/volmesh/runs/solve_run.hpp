#pragma once
// One solve as `volmesh solve` runs it once the mesh and its domain are there: the space, the
// problem on the domain, the solve, and the fields its output shows.
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "volmesh/runs/solve_setup.hpp"

namespace volmesh::cli {

// Throws InputError "problem sine is a Poisson problem: use volmesh solve poisson" when the
// problem is not of `kind` ("poisson" or "elasticity"); returns the problem's kind.
fem::ProblemKind require_problem_kind(const std::string& kind, const ProblemSpec& problem);

struct SolveRequest {
  std::string kind;  // "poisson" or "elasticity"
  ProblemSpec problem;
  std::string space;          // empty: `default_space`, else chosen from the cells
  std::string default_space;  // the mesher's (MesherInfo::default_space)
  // The mesh is its own domain: its boundary points are on the true boundary already (a
  // projection along normals could leave a point at a sharp edge for another surface).
  bool own_boundary = false;
  Solver solver;
  // The boundary tags the problem's conditions are matched against: empty for the mesh's own;
  // over all ranks for a mesh in pieces (boundary_tags_over_ranks), where a piece may lack one.
  std::vector<std::string> tag_names;
  // Receives the user problem's source check, if any, before the solve starts.
  std::function<void(const std::string&)> warn;
};

struct SolveRun {
  SpaceChoice space;
  Index dofs = 0;
  fem::LinearSolveReport report;
  std::optional<fem::ErrorNorms> errors;
  // Poisson: "u" (at the points, or the cells for finite volumes) and "error"; elasticity:
  // "displacement", "error" and "von_mises" (scalar_fields, vector_fields).
  MeshFields fields;
  std::string warning;
  // The problem's set-up here, and the output fields' evaluation.
  double problem_seconds = 0.0, fields_seconds = 0.0;
};

// The stages "setup" and "errors" are fem::stage's. Throws InputError for what the problem
// or the space refuses.
SolveRun solve_problem(const SolveRequest& request, const Domain& domain, const PolyMesh& mesh,
                       const Progress& progress = {});

// `volmesh solve --json`'s figures but its output, seconds and mesher: problem, kind, domain,
// space, cells, points, dofs, unknowns, linear_solver, iterations, residual, errors (l2, linf,
// h1; null without an exact solution), and the warning if any.
nlohmann::json solve_summary(const SolveRequest& request, const SolveRun& run,
                             const std::string& domain_name, const PolyMesh& mesh);

}  // namespace volmesh::cli
