// −∇·(k∇u) = f on any of the spaces (fem.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "fe_assembly.hpp"
#include "fe_shared.hpp"
#include "volmesh/fem/fem.hpp"

namespace volmesh::fem {
namespace {

using detail::CellPoints;
using detail::FeSpace;
using detail::LocalWork;
using detail::Rule;
using Clock = std::chrono::steady_clock;

void poisson_local(const FeSpace& space, Index c, double conductivity, const ScalarFunction& source,
                   LocalWork& work) {
  const Eigen::Index n =
      static_cast<Eigen::Index>(space.cell_nodes(c).size()) + space.internal_nodes();
  work.k.setZero(n, n);
  work.f.setZero(n);
  space.cell_points(c, Rule::stiffness, work.stiffness);
  const CellPoints& s = work.stiffness;
  for (const auto& g : s.groups) {
    const int* nodes = s.nodes.data() + g.node_begin;
    for (int p = g.point_begin; p < g.point_begin + g.point_count; ++p) {
      const Vec3* grad = s.gradient.data() + s.shape_begin[p];
      const double w = s.weight[p] * conductivity;
      for (int a = 0; a < g.node_count; ++a) {
        const Vec3 wa = w * grad[a];
        for (int b = 0; b < g.node_count; ++b) work.k(nodes[a], nodes[b]) += wa.dot(grad[b]);
      }
    }
  }
  if (!source) return;
  space.cell_points(c, Rule::load, work.load);
  const CellPoints& l = work.load;
  for (const auto& g : l.groups) {
    const int* nodes = l.nodes.data() + g.node_begin;
    for (int p = g.point_begin; p < g.point_begin + g.point_count; ++p) {
      const double wf = l.weight[p] * source(l.x[p]);
      const double* value = l.value.data() + l.shape_begin[p];
      for (int a = 0; a < g.node_count; ++a) work.f[nodes[a]] += wf * value[a];
    }
  }
}

struct CellResult {
  double mean = 0.0;
  double l2 = 0.0;  // ∫ (u − u_h)²
  double h1 = 0.0;  // ∫ |∇u − ∇u_h|²
};

}  // namespace

ScalarSolution solve_poisson(const PolyMesh& mesh, const PoissonProblem& problem, Space space_kind,
                             const LinearSolverOptions& options) {
  const auto start = Clock::now();
  const std::vector<double> conductivity =
      detail::per_cell(mesh, problem.conductivity, "conductivity");
  for (const auto& [region, k] : problem.conductivity)
    if (!(k > 0.0) || !std::isfinite(k))
      throw InputError("conductivity of region " + std::to_string(region) + " is not positive (" +
                       std::to_string(k) + ")");
  const auto conditions = detail::conditions_per_tag(mesh, problem.boundary);
  std::vector<char> dirichlet(conditions.size(), 0), neumann(conditions.size(), 0);
  for (std::size_t t = 0; t < conditions.size(); ++t)
    if (conditions[t]) {
      const bool is_dirichlet = conditions[t]->kind == ScalarBoundaryCondition::Kind::dirichlet;
      dirichlet[t] = is_dirichlet;
      neumann[t] = !is_dirichlet;
    }
  if (std::find(dirichlet.begin(), dirichlet.end(), 1) == dirichlet.end())
    throw InputError(
        "no Dirichlet boundary condition on any boundary face: the solution is "
        "determined only up to a constant");

  const auto space = detail::make_space(mesh, space_kind);
  const detail::LocalSystem local = [&](Index c, LocalWork& work) {
    poisson_local(*space, c, conductivity[c], problem.source, work);
  };
  detail::GlobalSystem system = detail::assemble_cells(*space, 1, local);
  detail::add_boundary_load(
      mesh, *space, 1, neumann, problem.to_true_boundary,
      [&](Index tag, const Vec3& at, double* out) {
        const auto& value = conditions[tag]->value;
        out[0] = value ? value(at) : 0.0;
      },
      system.rhs);

  const Index nn = space->num_nodes();
  const std::vector<Index> dirichlet_tag = detail::lowest_marked_tag(mesh, *space, dirichlet);
  std::vector<char> fixed(nn, 0);
  Eigen::VectorXd fixed_values = Eigen::VectorXd::Zero(nn);
  for (Index n = 0; n < nn; ++n) {
    if (dirichlet_tag[n] == kNoIndex) continue;
    fixed[n] = 1;
    const auto& value = conditions[dirichlet_tag[n]]->value;
    if (value)
      fixed_values[n] =
          value(detail::on_true_boundary(problem.to_true_boundary, space->node_point[n]));
  }

  ScalarSolution out;
  out.dofs = nn;
  out.solve.assembly_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const Eigen::VectorXd u =
      solve_spd_constrained(system.lower, system.rhs, fixed, fixed_values, options, out.solve);

  out.point_values.assign(mesh.num_points(), std::numeric_limits<double>::quiet_NaN());
  for (Index p = 0; p < mesh.num_points(); ++p)
    if (space->point_node[p] != kNoIndex) out.point_values[p] = u[space->point_node[p]];

  // Cell means and error integrals, per cell in parallel, summed in cell order. The stiffness
  // rule integrates u_h exactly; the degree-5 rule is for the errors.
  const Rule rule = problem.exact ? Rule::accurate : Rule::stiffness;
  std::vector<CellResult> cells(mesh.num_cells());
  detail::for_each_cell(0, mesh.num_cells(), [&](Index c, LocalWork& work) {
    Eigen::VectorXd local_u;
    detail::cell_unknowns(*space, 1, local, c, u, work, local_u);
    space->cell_points(c, rule, work.load);
    const CellPoints& q = work.load;
    CellResult& r = cells[c];
    double volume = 0.0;
    for (const auto& g : q.groups) {
      const int* nodes = q.nodes.data() + g.node_begin;
      for (int p = g.point_begin; p < g.point_begin + g.point_count; ++p) {
        const double* value = q.value.data() + q.shape_begin[p];
        const Vec3* grad = q.gradient.data() + q.shape_begin[p];
        double uh = 0.0;
        Vec3 grad_uh = Vec3::Zero();
        for (int a = 0; a < g.node_count; ++a) {
          uh += value[a] * local_u[nodes[a]];
          grad_uh += local_u[nodes[a]] * grad[a];
        }
        const double w = q.weight[p];
        volume += w;
        r.mean += w * uh;
        if (problem.exact) r.l2 += w * std::pow(problem.exact(q.x[p]) - uh, 2);
        if (problem.exact_gradient)
          r.h1 += w * (problem.exact_gradient(q.x[p]) - grad_uh).squaredNorm();
      }
    }
    r.mean /= volume;
  });
  out.cell_values.resize(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) out.cell_values[c] = cells[c].mean;
  if (problem.exact) {
    double linf = 0.0;
    for (Index n = 0; n < nn; ++n)
      linf = std::max(linf, std::abs(problem.exact(space->node_point[n]) - u[n]));
    out.errors = detail::error_norms(cells, bool(problem.exact_gradient), linf);
  }
  return out;
}

}  // namespace volmesh::fem
