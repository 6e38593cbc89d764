// −∇·σ(u) = b, σ = λ tr(ε) I + 2μ ε, on any of the spaces (fem.hpp); three unknowns per node.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

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

void elasticity_local(const FeSpace& space, Index c, const LameParameters& lame,
                      const VectorFunction& body_force, LocalWork& work) {
  const Eigen::Index n =
      3 * (static_cast<Eigen::Index>(space.cell_nodes(c).size()) + space.internal_nodes());
  work.k.setZero(n, n);
  work.f.setZero(n);
  space.cell_points(c, Rule::stiffness, work.stiffness);
  const CellPoints& s = work.stiffness;
  for (const auto& g : s.groups) {
    const int* nodes = s.nodes.data() + g.node_begin;
    for (int p = g.point_begin; p < g.point_begin + g.point_count; ++p) {
      const Vec3* grad = s.gradient.data() + s.shape_begin[p];
      const double w = s.weight[p];
      for (int a = 0; a < g.node_count; ++a) {
        const Vec3 wa = w * grad[a];
        for (int b = 0; b < g.node_count; ++b) {
          // Block (a, b): λ ∇N_a ∇N_bᵀ + μ ∇N_b ∇N_aᵀ + μ (∇N_a·∇N_b) I.
          Eigen::Matrix3d block =
              lame.lambda * wa * grad[b].transpose() + lame.mu * grad[b] * wa.transpose();
          block.diagonal().array() += lame.mu * wa.dot(grad[b]);
          work.k.block<3, 3>(3 * nodes[a], 3 * nodes[b]) += block;
        }
      }
    }
  }
  if (!body_force) return;
  space.cell_points(c, Rule::load, work.load);
  const CellPoints& l = work.load;
  for (const auto& g : l.groups) {
    const int* nodes = l.nodes.data() + g.node_begin;
    for (int p = g.point_begin; p < g.point_begin + g.point_count; ++p) {
      const Vec3 wb = l.weight[p] * body_force(l.x[p]);
      const double* value = l.value.data() + l.shape_begin[p];
      for (int a = 0; a < g.node_count; ++a) work.f.segment<3>(3 * nodes[a]) += value[a] * wb;
    }
  }
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
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();  // mean over the cell
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
  const auto start = Clock::now();
  const std::vector<LameParameters> lame = lame_per_cell(mesh, problem.material);
  const auto conditions = detail::conditions_per_tag(mesh, problem.boundary);
  std::vector<char> displacement(conditions.size(), 0), traction(conditions.size(), 0);
  for (std::size_t t = 0; t < conditions.size(); ++t)
    if (conditions[t]) {
      const bool fixed = conditions[t]->kind == VectorBoundaryCondition::Kind::displacement;
      displacement[t] = fixed;
      traction[t] = !fixed;
    }
  if (std::find(displacement.begin(), displacement.end(), 1) == displacement.end())
    throw InputError(
        "no displacement boundary condition on any boundary face: the displacement is "
        "determined only up to a rigid motion");

  const auto space = detail::make_space(mesh, space_kind);
  const detail::LocalSystem local = [&](Index c, LocalWork& work) {
    elasticity_local(*space, c, lame[c], problem.body_force, work);
  };
  detail::GlobalSystem system = detail::assemble_cells(*space, 3, local);
  detail::add_boundary_load(
      mesh, *space, 3, traction, problem.to_true_boundary,
      [&](Index tag, const Vec3& at, double* out) {
        const auto& value = conditions[tag]->value;
        const Vec3 t = value ? value(at) : Vec3::Zero();
        std::copy(t.data(), t.data() + 3, out);
      },
      system.rhs);

  const Index nn = space->num_nodes();
  const std::vector<Index> fixed_tag = detail::lowest_marked_tag(mesh, *space, displacement);
  std::vector<char> fixed(3 * std::size_t(nn), 0);
  Eigen::VectorXd fixed_values = Eigen::VectorXd::Zero(3 * nn);
  for (Index n = 0; n < nn; ++n) {
    if (fixed_tag[n] == kNoIndex) continue;
    std::fill_n(fixed.begin() + 3 * n, 3, 1);
    const auto& value = conditions[fixed_tag[n]]->value;
    if (value)
      fixed_values.segment<3>(3 * n) =
          value(detail::on_true_boundary(problem.to_true_boundary, space->node_point[n]));
  }

  VectorSolution out;
  out.dofs = 3 * nn;
  out.solve.assembly_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const Eigen::VectorXd u =
      solve_spd_constrained(system.lower, system.rhs, fixed, fixed_values, options, out.solve);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.point_values.assign(mesh.num_points(), Vec3(nan, nan, nan));
  for (Index p = 0; p < mesh.num_points(); ++p)
    if (space->point_node[p] != kNoIndex)
      out.point_values[p] = u.segment<3>(3 * space->point_node[p]);

  // Mean stresses and error integrals, per cell in parallel, summed in cell order. The
  // stiffness rule integrates σ(u_h) exactly; the degree-5 rule is for the errors.
  const Rule rule = problem.exact ? Rule::accurate : Rule::stiffness;
  std::vector<CellResult> cells(mesh.num_cells());
  detail::for_each_cell(0, mesh.num_cells(), [&](Index c, LocalWork& work) {
    Eigen::VectorXd local_u;
    detail::cell_unknowns(*space, 3, local, c, u, work, local_u);
    space->cell_points(c, rule, work.load);
    const CellPoints& q = work.load;
    CellResult& r = cells[c];
    double volume = 0.0;
    for (const auto& g : q.groups) {
      const int* nodes = q.nodes.data() + g.node_begin;
      for (int p = g.point_begin; p < g.point_begin + g.point_count; ++p) {
        const double* value = q.value.data() + q.shape_begin[p];
        const Vec3* grad = q.gradient.data() + q.shape_begin[p];
        Vec3 uh = Vec3::Zero();
        Eigen::Matrix3d grad_uh = Eigen::Matrix3d::Zero();  // row i: ∇u_i
        for (int a = 0; a < g.node_count; ++a) {
          const Vec3 ua = local_u.segment<3>(3 * nodes[a]);
          uh += value[a] * ua;
          grad_uh += ua * grad[a].transpose();
        }
        const double w = q.weight[p];
        volume += w;
        r.stress += w * isotropic_stress(grad_uh, lame[c]);
        if (problem.exact) r.l2 += w * (problem.exact(q.x[p]) - uh).squaredNorm();
        if (problem.exact_gradient)
          r.h1 += w * (problem.exact_gradient(q.x[p]) - grad_uh).squaredNorm();
      }
    }
    r.stress /= volume;
  });
  out.cell_stress.resize(cells.size());
  out.von_mises.resize(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    out.cell_stress[c] = cells[c].stress;
    out.von_mises[c] = von_mises(cells[c].stress);
  }
  if (problem.exact) {
    double linf = 0.0;
    for (Index n = 0; n < nn; ++n)
      linf = std::max(linf, (problem.exact(space->node_point[n]) - u.segment<3>(3 * n)).norm());
    out.errors = detail::error_norms(cells, bool(problem.exact_gradient), linf);
  }
  return out;
}

}  // namespace volmesh::fem
