// −∇·σ(u) = b, σ = λ tr(ε) I + 2μ ε, on any of the spaces (fem.hpp); three unknowns per node.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "fe_solve.hpp"
#include "volmesh/fem/fem.hpp"

namespace volmesh::fem {
namespace {

using detail::CellPoints;
using detail::FeSpace;
using detail::LocalWork;
using detail::Rule;

void elasticity_local(const FeSpace& space, Index c, const LameParameters& lame,
                      const VectorFunction& body_force, LocalWork& work) {
  const CellPoints& s = detail::begin_local(space, c, 3, work);
  detail::for_each_point(s, [&](int p, const int* nodes, int count) {
    const Vec3* grad = s.gradient.data() + s.shape_begin[p];
    const double w = s.weight[p];
    for (int a = 0; a < count; ++a) {
      const Vec3 wa = w * grad[a];
      for (int b = 0; b < count; ++b) {
        // Block (a, b): λ ∇N_a ∇N_bᵀ + μ ∇N_b ∇N_aᵀ + μ (∇N_a·∇N_b) I.
        Eigen::Matrix3d block =
            lame.lambda * wa * grad[b].transpose() + lame.mu * grad[b] * wa.transpose();
        block.diagonal().array() += lame.mu * wa.dot(grad[b]);
        work.k.block<3, 3>(3 * nodes[a], 3 * nodes[b]) += block;
      }
    }
  });
  // The P-wave modulus scales the stabilisation like the stiffness of a one-axis strain.
  detail::add_stabilization<3>(s, lame.lambda + 2.0 * lame.mu, work.k);
  if (!body_force) return;
  const CellPoints& l = detail::load_points(space, c, work);
  detail::for_each_point(l, [&](int p, const int* nodes, int count) {
    const Vec3 wb = l.weight[p] * body_force(l.x[p]);
    const double* value = l.value.data() + l.shape_begin[p];
    for (int a = 0; a < count; ++a) work.f.segment<3>(3 * nodes[a]) += value[a] * wb;
  });
}

std::vector<LameParameters> lame_per_cell(const PolyMesh& mesh,
                                          const std::map<Index, IsotropicMaterial>& materials) {
  for (const auto& [region, m] : materials)
    if (!(m.young > 0.0) || !std::isfinite(m.young) || !(m.poisson > -1.0 && m.poisson < 0.5)) {
      std::ostringstream message;
      message << "material of region " << region << ": Young's modulus " << m.young
              << " and Poisson's ratio " << m.poisson << " (need E > 0, -1 < nu < 0.5)";
      throw InputError(message.str());
    }
  std::vector<LameParameters> out;
  for (const IsotropicMaterial& m : detail::per_cell(mesh, materials, "material"))
    out.push_back(lame_parameters(m));
  return out;
}

struct CellResult {
  double volume = 0.0;
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();  // integral over the cell
  double l2 = 0.0;                                   // ∫ |u − u_h|²
  double h1 = 0.0;                                   // ∫ |∇u − ∇u_h|² (Frobenius)
};

}  // namespace

LameParameters lame_parameters(const IsotropicMaterial& m) {
  return {m.young * m.poisson / ((1.0 + m.poisson) * (1.0 - 2.0 * m.poisson)),
          m.young / (2.0 * (1.0 + m.poisson))};
}

Eigen::Matrix3d isotropic_stress(const Eigen::Matrix3d& displacement_gradient,
                                 const LameParameters& lame) {
  const Eigen::Matrix3d strain = 0.5 * (displacement_gradient + displacement_gradient.transpose());
  return lame.lambda * strain.trace() * Eigen::Matrix3d::Identity() + 2.0 * lame.mu * strain;
}

double von_mises(const Eigen::Matrix3d& stress) {
  const Eigen::Matrix3d s = stress - stress.trace() / 3.0 * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * s.cwiseProduct(s).sum());
}

VectorSolution solve_elasticity(const PolyMesh& mesh, const ElasticityProblem& problem,
                                Space space_kind, const LinearSolverOptions& options) {
  const Clock::time_point start = Clock::now();
  const std::vector<LameParameters> lame = lame_per_cell(mesh, problem.material);

  VectorSolution out;
  const detail::SolvedField field = detail::solve_field<3>(
      mesh, space_kind, problem.boundary, problem.to_true_boundary,
      [&](const FeSpace& space, Index c, LocalWork& work) {
        elasticity_local(space, c, lame[c], problem.body_force, work);
      },
      options, start, out.solve);
  const Clock::time_point results = Clock::now();
  out.dofs = 3 * static_cast<Index>(field.nodes);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.point_values.assign(mesh.num_points(), Vec3(nan, nan, nan));
  for (Index p = 0; p < mesh.num_points(); ++p)
    if (field.space->point_node[p] != kNoIndex)
      out.point_values[p] = field.u.segment<3>(3 * field.space->point_node[p]);

  // Mean stresses and error integrals, per cell in parallel, summed in cell order. The
  // stiffness rule integrates σ(u_h) exactly; the degree-5 rule is for the errors.
  volmesh::report(options.progress, "results", detail::kResultsStart);
  const std::vector<CellResult> cells = detail::integrate_cells<3, CellResult>(
      field, problem.exact ? Rule::accurate : Rule::stiffness,
      [&](Index c, const Vec3& x, double w, const detail::PointValue<3>& v, CellResult& r) {
        r.stress += w * isotropic_stress(v.gradient, lame[c]);
        if (problem.exact) r.l2 += w * (problem.exact(x) - v.u).squaredNorm();
        if (problem.exact_gradient)
          r.h1 += w * (problem.exact_gradient(x) - v.gradient).squaredNorm();
      });
  out.cell_stress.resize(cells.size());
  out.von_mises.resize(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    out.cell_stress[c] = cells[c].stress / cells[c].volume;
    out.von_mises[c] = von_mises(out.cell_stress[c]);
  }
  if (problem.exact)
    out.errors = detail::error_norms(cells, bool(problem.exact_gradient),
                                     detail::nodal_max_error<3>(field, problem.exact),
                                     field.in_pieces);
  out.solve.errors_seconds = seconds_since(results);
  return out;
}

}  // namespace volmesh::fem
