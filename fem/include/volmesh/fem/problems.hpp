#pragma once
// The problem library (docs/methods.md, "Problems"): named manufactured and analytic solutions,
// and cases a user gives as expressions, turned into a PoissonProblem / ElasticityProblem for a
// domain and the boundary tag names of a mesh of it. Boundary data are evaluated on the TRUE
// boundary (true_boundary_map).
//
// Poisson, −∇·(k∇u) = f:
//   sine            u = sin(x+0.3)·sin(2y+0.1)·sin(3z+0.7), k = 1, f = 14u, u given on every tag
//   sine-neumann    the same u and f; u given on the first tag, the flux k∂u/∂n (normal of the
//                   domain at the true boundary point) on the others; needs two tags or more
//   patch-linear    u = 1 + 2x − y + 3z, f = 0, k = 2.5 in every region (one linear field
//                   keeps the flux continuous across an interface only when k is the same on
//                   both sides), u given on every tag: reproduced exactly by linear spaces
//   multi-material  k = region label, f = 1, u = 0 on every tag, no exact solution
//                   (builtin:primitives: seven regions, k from 1 to 7)
// Elasticity, −∇·σ(u) = b:
//   lame            thick-walled sphere a = 1/2 ≤ r ≤ b = 1 (builtin:thick-sphere) under the
//                   internal pressure p = 1, E = 1, ν = 0.3: u = (A r + B/r²) e_r with
//                   A = p a³ / ((3λ+2μ)(b³−a³)), B = p a³ b³ / (4μ(b³−a³)), the solution with a
//                   traction-free outer surface. Tag "inner" carries the traction −p n; tag
//                   "outer" the exact displacement (Dirichlet: it removes the rigid motions
//                   without a constraint; the outer traction is zero by construction).
//   elastic-patch   u = (0.1 + 0.2x − 0.1y + 0.3z, −0.2 + 0.1x + 0.4y − 0.2z,
//                   0.05 − 0.3x + 0.1y + 0.2z), b = 0, E = 1, ν = 0.3 in every region,
//                   u given on every tag: reproduced exactly by linear spaces
#include <string>
#include <vector>

#include "volmesh/domain/domain.hpp"
#include "volmesh/domain/outer_boundary.hpp"
#include "volmesh/fem/problem.hpp"

namespace volmesh::fem {

enum class ProblemKind { poisson, elasticity };

struct ProblemInfo {
  std::string name;
  ProblemKind kind;
  std::string summary;  // one line for --help and reports
};
const std::vector<ProblemInfo>& problem_catalogue();
std::vector<std::string> problem_names();  // in catalogue order
// Throws InputError listing the valid names for an unknown one.
ProblemKind problem_kind(const std::string& name);

// `tags` are the boundary tag names of the mesh (PolyMesh::tag_names); every one gets a
// condition. Coefficients are given for every region of domain.regions(). The problem's
// functions refer to `domain`, which must outlive it. Throws InputError for an unknown name,
// a name of the other kind, or tags the problem cannot serve (e.g. "lame" without "inner"
// and "outer").
PoissonProblem make_poisson_problem(const std::string& name, const Domain& domain,
                                    const std::vector<std::string>& tags);
ElasticityProblem make_elasticity_problem(const std::string& name, const Domain& domain,
                                          const std::vector<std::string>& tags);

// A user's case: u = exact_text and f = source_text (muparser expressions in x, y, z,
// expression.hpp; an empty text is "not given"), k in every region, u given on every tag
// (0 without an exact solution). Without a source, f = −kΔu by finite differences. With
// both, −kΔu (finite differences) is compared with f at 64 points inside the domain and
// `warning` says where they differ by more than 3e-4 of the largest |f| or |kΔu| seen.
// The gradient of the exact solution (for H1 errors) is taken by central differences.
struct UserPoissonProblem {
  PoissonProblem problem;
  std::string warning;  // empty when the source matches or is not checked
};
UserPoissonProblem user_poisson_problem(const std::string& exact_text,
                                        const std::string& source_text, double k,
                                        const Domain& domain,
                                        const std::vector<std::string>& tags);

// The closest point of the domain's outer boundary, for PoissonProblem::to_true_boundary:
// outer_boundary_map (volmesh/domain/outer_boundary.hpp), exact for analytic solids.
inline PointMap true_boundary_map(const Domain& domain) { return outer_boundary_map(domain); }

// Fourth-order central differences with step h: used to check sources and exact solutions
// and to differentiate user expressions.
double finite_difference_laplacian(const ScalarFunction& u, const Vec3& p, double h);
Vec3 finite_difference_gradient(const ScalarFunction& u, const Vec3& p, double h);

}  // namespace volmesh::fem
