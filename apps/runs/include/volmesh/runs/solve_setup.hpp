#pragma once
// What `solve`, `study` and `demo` share: the space a mesh is solved in, the problem (named,
// or given as expressions) and the solve itself.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/core/progress.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/fem/fem.hpp"
#include "volmesh/fem/problems.hpp"
#include "volmesh/io/mesh_io.hpp"

namespace volmesh::cli {

// A finite-element space or the cell-centred finite volumes ("fv", Poisson only).
struct SpaceChoice {
  std::optional<fem::Space> fe;  // empty: finite volumes
  std::string name() const { return fe ? fem::space_name(*fe) : "fv"; }
};
// `requested` empty: the mesher's default space (MesherInfo::default_space) if it has one;
// otherwise p1 for a mesh of tets, q1 for a mesh of hexes, polyhedral for any other. Throws
// InputError for an unknown name.
SpaceChoice choose_space(const std::string& requested, const std::string& default_space,
                         const PolyMesh& mesh);

// --problem NAME, or a user's case from --exact/--source/--k (Poisson only).
struct ProblemSpec {
  std::string name;          // empty when expressions are given
  std::string exact, source;
  double k = 1.0;
  bool user() const { return name.empty(); }
  std::string label() const { return user() ? std::string("user expressions") : name; }
};
// Refuses a spec with both a name and expressions, or neither (InputError).
fem::ProblemKind problem_kind(const ProblemSpec& spec);

// The problem on a mesh of `domain` whose boundary tags (which get conditions) are
// `tag_names`: the mesh's, or over all ranks for a mesh in pieces (boundary_tags_over_ranks).
// `warning` receives the user problem's source check, if any.
fem::PoissonProblem poisson_problem(const ProblemSpec& spec, const Domain& domain,
                                    const std::vector<std::string>& tag_names,
                                    std::string* warning = nullptr);
fem::ElasticityProblem elasticity_problem(const ProblemSpec& spec, const Domain& domain,
                                          const std::vector<std::string>& tag_names);

// Who runs CG on the large systems (LinearSolverOptions::Backend).
using SolverBackend = fem::LinearSolverOptions::Backend;
// By name: auto, eigen, petsc (--solver).
const std::map<std::string, SolverBackend>& solver_backends();

// The backend, and in a distributed run each cell's rank (LinearSolverOptions::cell_rank),
// or, when each rank holds its piece of the mesh, the piece's point numbers and owners
// (LinearSolverOptions::piece_points).
struct Solver {
  SolverBackend backend = SolverBackend::automatic;
  const std::vector<Index>* cell_rank = nullptr;
  const std::vector<std::int64_t>* piece_points = nullptr;
  const std::vector<int>* piece_owner = nullptr;
};

fem::ScalarSolution solve_scalar(const PolyMesh& mesh, const fem::PoissonProblem& problem,
                                 const SpaceChoice& space, const Progress& progress = {},
                                 const Solver& solver = {});
// Throws InputError for finite volumes (Poisson only).
fem::VectorSolution solve_vector(const PolyMesh& mesh, const fem::ElasticityProblem& problem,
                                 const SpaceChoice& space, const Progress& progress = {},
                                 const Solver& solver = {});

// What a VTU shows of a solution. Poisson: point data "u" (cell data for finite volumes,
// whose unknowns live in the cells) and "error" = u_h − u where the problem has an exact
// solution. Elasticity: point data "displacement" and "error" (3 components), cell data
// "von_mises". The writer adds the cell "region".
MeshFields scalar_fields(const PolyMesh& mesh, const fem::ScalarSolution& solution,
                         const fem::PoissonProblem& problem);
MeshFields vector_fields(const PolyMesh& mesh, const fem::VectorSolution& solution,
                         const fem::ElasticityProblem& problem);

// A mesh read from a file taken as its own domain: its boundary is the true boundary and
// its regions are the mesh's (for `solve --mesh M` without --domain). Throws InputError
// when the boundary is not a closed surface.
std::unique_ptr<Domain> mesh_as_domain(const PolyMesh& mesh, const std::string& name);

}  // namespace volmesh::cli
