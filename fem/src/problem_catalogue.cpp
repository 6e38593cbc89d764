// The names of the problem library.
#include "volmesh/core/errors.hpp"
#include "volmesh/fem/problems.hpp"

namespace volmesh::fem {

const std::vector<ProblemInfo>& problem_catalogue() {
  static const std::vector<ProblemInfo> all{
      {"sine", ProblemKind::poisson,
       "u = sin(x+0.3)sin(2y+0.1)sin(3z+0.7), k = 1, u on every boundary tag"},
      {"sine-neumann", ProblemKind::poisson,
       "the sine solution with u on the first tag and the flux on the others"},
      {"patch-linear", ProblemKind::poisson,
       "u = 1 + 2x - y + 3z, k = 2.5: exact for linear spaces"},
      {"multi-material", ProblemKind::poisson,
       "k = region label, f = 1, u = 0 on every tag (no exact solution)"},
      {"lame", ProblemKind::elasticity,
       "thick-walled sphere 1/2 <= r <= 1 under internal pressure 1 (analytic)"},
      {"elastic-patch", ProblemKind::elasticity,
       "linear displacement, no body force: exact for linear spaces"},
  };
  return all;
}

std::vector<std::string> problem_names() {
  std::vector<std::string> names;
  for (const ProblemInfo& p : problem_catalogue()) names.push_back(p.name);
  return names;
}

ProblemKind problem_kind(const std::string& name) {
  std::string valid;
  for (const ProblemInfo& p : problem_catalogue()) {
    if (p.name == name) return p.kind;
    valid += (valid.empty() ? "" : ", ") + p.name;
  }
  throw InputError("problem " + name + ": unknown (valid: " + valid + ")");
}

}  // namespace volmesh::fem
