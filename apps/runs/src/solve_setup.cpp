#include "volmesh/runs/solve_setup.hpp"

#include "volmesh/core/boundary.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/fem/finite_volume.hpp"

namespace volmesh::cli {

namespace {

// The mesh's boundary as a surface domain, reporting the mesh's regions.
class MeshDomain final : public Domain {
 public:
  MeshDomain(SurfaceDomain surface, std::vector<Index> regions)
      : surface_(std::move(surface)), regions_(std::move(regions)) {}
  using Domain::crossings;
  using Domain::region;
  // Inside: the lowest region (the mesh knows where each region is; the problems only ask
  // whether a point is inside).
  Index region(const Vec3& p) const override {
    return surface_.region(p) != 0 ? regions_.front() : 0;
  }
  std::vector<Crossing> crossings(const Vec3& a, const Vec3& b) const override {
    return surface_.crossings(a, b);
  }
  Vec3 normal(const Vec3& p) const override { return surface_.normal(p); }
  Box3 bounds() const override { return surface_.bounds(); }
  std::vector<Index> regions() const override { return regions_; }

 private:
  SurfaceDomain surface_;
  std::vector<Index> regions_;
};

}  // namespace

SpaceChoice choose_space(const std::string& requested, const std::string& default_space,
                         const PolyMesh& mesh) {
  if (requested == "fv") return {};
  if (!requested.empty()) {
    if (const auto s = fem::space_from_name(requested)) return {*s};
    throw InputError("--space " + requested + ": unknown (p1, p2, q1, polyhedral, fv)");
  }
  if (!default_space.empty()) return choose_space(default_space, "", mesh);
  const CellFaces cell_faces = build_cell_faces(mesh);
  bool tets = mesh.num_cells() > 0, hexes = mesh.num_cells() > 0;
  for (Index c = 0; c < mesh.num_cells() && (tets || hexes); ++c) {
    const CellShape shape = classify_cell(mesh, cell_faces, c).shape;
    tets = tets && shape == CellShape::Tetrahedron;
    hexes = hexes && shape == CellShape::Hexahedron;
  }
  return {tets ? fem::Space::p1 : hexes ? fem::Space::q1 : fem::Space::polyhedral};
}

fem::ProblemKind problem_kind(const ProblemSpec& spec) {
  const bool expressions = !spec.exact.empty() || !spec.source.empty();
  if (!spec.name.empty() && expressions)
    throw InputError("--problem " + spec.name + ": give either a named problem or --exact/--source");
  if (spec.name.empty() && !expressions)
    throw InputError("no problem: give --problem NAME or --exact/--source expressions");
  return spec.user() ? fem::ProblemKind::poisson : fem::problem_kind(spec.name);
}

fem::PoissonProblem poisson_problem(const ProblemSpec& spec, const Domain& domain,
                                    const std::vector<std::string>& tag_names,
                                    std::string* warning) {
  if (!spec.user()) return fem::make_poisson_problem(spec.name, domain, tag_names);
  fem::UserPoissonProblem p =
      fem::user_poisson_problem(spec.exact, spec.source, spec.k, domain, tag_names);
  if (warning) *warning = p.warning;
  return std::move(p.problem);
}

fem::ElasticityProblem elasticity_problem(const ProblemSpec& spec, const Domain& domain,
                                          const std::vector<std::string>& tag_names) {
  if (spec.user())
    throw InputError("--exact/--source: user expressions define Poisson problems only");
  return fem::make_elasticity_problem(spec.name, domain, tag_names);
}

const std::map<std::string, SolverBackend>& solver_backends() {
  static const std::map<std::string, SolverBackend> names{{"auto", SolverBackend::automatic},
                                                          {"eigen", SolverBackend::eigen},
                                                          {"petsc", SolverBackend::petsc}};
  return names;
}

namespace {

fem::LinearSolverOptions solver_options(const Progress& progress, const Solver& solver) {
  fem::LinearSolverOptions options;
  options.progress = progress;
  options.backend = solver.backend;
  options.cell_rank = solver.cell_rank;
  options.piece_points = solver.piece_points;
  options.piece_owner = solver.piece_owner;
  return options;
}

}  // namespace

fem::ScalarSolution solve_scalar(const PolyMesh& mesh, const fem::PoissonProblem& problem,
                                 const SpaceChoice& space, const Progress& progress,
                                 const Solver& solver) {
  const fem::LinearSolverOptions options = solver_options(progress, solver);
  if (space.fe) return fem::solve_poisson(mesh, problem, *space.fe, options);
  return fem::solve_poisson_fv(mesh, problem, options);
}

fem::VectorSolution solve_vector(const PolyMesh& mesh, const fem::ElasticityProblem& problem,
                                 const SpaceChoice& space, const Progress& progress,
                                 const Solver& solver) {
  if (!space.fe)
    throw InputError("--space fv: finite volumes solve Poisson problems only");
  const fem::LinearSolverOptions options = solver_options(progress, solver);
  return fem::solve_elasticity(mesh, problem, *space.fe, options);
}

MeshFields scalar_fields(const PolyMesh& mesh, const fem::ScalarSolution& solution,
                         const fem::PoissonProblem& problem) {
  const bool at_points = !solution.point_values.empty();
  std::vector<Vec3> where = mesh.points;
  if (!at_points) {
    const MeshGeometry g = mesh_geometry(mesh, build_cell_faces(mesh));
    where.clear();
    for (const CellGeometry& c : g.cells) where.push_back(c.centre);
  }
  const std::vector<double>& u = at_points ? solution.point_values : solution.cell_values;
  std::vector<Field> fields{{"u", 1, u}};
  if (problem.exact) {
    Field error{"error", 1, {}};
    for (std::size_t i = 0; i < u.size(); ++i) error.values.push_back(u[i] - problem.exact(where[i]));
    fields.push_back(std::move(error));
  }
  MeshFields out;
  (at_points ? out.point : out.cell) = std::move(fields);
  return out;
}

MeshFields vector_fields(const PolyMesh& mesh, const fem::VectorSolution& solution,
                         const fem::ElasticityProblem& problem) {
  MeshFields out;
  Field displacement{"displacement", 3, {}}, error{"error", 3, {}};
  for (std::size_t i = 0; i < solution.point_values.size(); ++i) {
    const Vec3& u = solution.point_values[i];
    displacement.values.insert(displacement.values.end(), {u.x(), u.y(), u.z()});
    if (problem.exact) {
      const Vec3 e = u - problem.exact(mesh.points[i]);
      error.values.insert(error.values.end(), {e.x(), e.y(), e.z()});
    }
  }
  out.point.push_back(std::move(displacement));
  if (problem.exact) out.point.push_back(std::move(error));
  out.cell.push_back({"von_mises", 1, solution.von_mises});
  return out;
}

std::unique_ptr<Domain> mesh_as_domain(const PolyMesh& mesh, const std::string& name) {
  std::vector<LabelledSurface> surfaces{{boundary_surface(mesh), 1, name + " (boundary)"}};
  std::vector<Index> regions = regions_of(mesh);
  if (regions.empty()) throw InputError(name + ": the mesh has no cells");
  return std::make_unique<MeshDomain>(SurfaceDomain(std::move(surfaces)), std::move(regions));
}

}  // namespace volmesh::cli
