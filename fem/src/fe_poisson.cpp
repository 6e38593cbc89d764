// −∇·(k∇u) = f on any of the spaces (fem.hpp).
#include <cmath>
#include <limits>

#include "fe_solve.hpp"
#include "volmesh/fem/fem.hpp"

namespace volmesh::fem {
namespace {

using detail::CellPoints;
using detail::FeSpace;
using detail::LocalWork;
using detail::Rule;

void poisson_local(const FeSpace& space, Index c, double conductivity, const ScalarFunction& source,
                   LocalWork& work) {
  const CellPoints& s = detail::begin_local(space, c, 1, work);
  detail::for_each_point(s, [&](int p, const int* nodes, int count) {
    const Vec3* grad = s.gradient.data() + s.shape_begin[p];
    const double w = s.weight[p] * conductivity;
    for (int a = 0; a < count; ++a) {
      const Vec3 wa = w * grad[a];
      for (int b = 0; b < count; ++b) work.k(nodes[a], nodes[b]) += wa.dot(grad[b]);
    }
  });
  detail::add_stabilization<1>(s, conductivity, work.k);
  if (!source) return;
  const CellPoints& l = detail::load_points(space, c, work);
  detail::for_each_point(l, [&](int p, const int* nodes, int count) {
    const double wf = l.weight[p] * source(l.x[p]);
    const double* value = l.value.data() + l.shape_begin[p];
    for (int a = 0; a < count; ++a) work.f[nodes[a]] += wf * value[a];
  });
}

struct CellResult {
  double volume = 0.0;
  double mean = 0.0;
  double l2 = 0.0;  // ∫ (u − u_h)²
  double h1 = 0.0;  // ∫ |∇u − ∇u_h|²
};

}  // namespace

ScalarSolution solve_poisson(const PolyMesh& mesh, const PoissonProblem& problem, Space space_kind,
                             const LinearSolverOptions& options) {
  const Clock::time_point start = Clock::now();
  const std::vector<double> conductivity =
      detail::per_cell(mesh, problem.conductivity, "conductivity");
  for (const auto& [region, k] : problem.conductivity)
    if (!(k > 0.0) || !std::isfinite(k))
      throw InputError("conductivity of region " + std::to_string(region) + " is not positive (" +
                       std::to_string(k) + ")");

  ScalarSolution out;
  const detail::SolvedField field = detail::solve_field<1>(
      mesh, space_kind, problem.boundary, problem.to_true_boundary,
      [&](const FeSpace& space, Index c, LocalWork& work) {
        poisson_local(space, c, conductivity[c], problem.source, work);
      },
      options, start, out.solve);
  const Clock::time_point results = Clock::now();
  out.dofs = static_cast<Index>(field.nodes);
  out.point_values.assign(mesh.num_points(), std::numeric_limits<double>::quiet_NaN());
  for (Index p = 0; p < mesh.num_points(); ++p)
    if (field.space->point_node[p] != kNoIndex)
      out.point_values[p] = field.u[field.space->point_node[p]];

  // Cell means and error integrals, per cell in parallel, summed in cell order. The stiffness
  // rule integrates u_h exactly; the degree-5 rule is for the errors.
  volmesh::report(options.progress, "results", detail::kResultsStart);
  const std::vector<CellResult> cells = detail::integrate_cells<1, CellResult>(
      field, problem.exact ? Rule::accurate : Rule::stiffness,
      [&](Index, const Vec3& x, double w, const detail::PointValue<1>& v, CellResult& r) {
        r.mean += w * v.u[0];
        if (problem.exact) r.l2 += w * std::pow(problem.exact(x) - v.u[0], 2);
        if (problem.exact_gradient)
          r.h1 += w * (problem.exact_gradient(x) - v.gradient.transpose()).squaredNorm();
      });
  out.cell_values.resize(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c)
    out.cell_values[c] = cells[c].mean / cells[c].volume;
  if (problem.exact)
    out.errors = detail::error_norms(cells, bool(problem.exact_gradient),
                                     detail::nodal_max_error<1>(field, problem.exact),
                                     field.in_pieces);
  out.solve.errors_seconds = seconds_since(results);
  return out;
}

}  // namespace volmesh::fem
