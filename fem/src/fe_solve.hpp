#pragma once
// The steps Poisson and elasticity share around their local systems: conditions split into
// essential and natural ones, the global system with the natural loads, the essential values
// at the nodes (taken on the true boundary), the constrained solve, and u_h at a cell's
// quadrature points afterwards. C is the number of unknowns per node (1 or 3), node-major.
#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "fe_assembly.hpp"
#include "fe_distributed.hpp"
#include "fe_pieces.hpp"
#include "fe_shared.hpp"
#include "volmesh/core/stopwatch.hpp"
#include "volmesh/fem/linear_solver.hpp"
#include "volmesh/fem/parallel.hpp"

namespace volmesh::fem::detail {

template <int C>
using NodeVector = Eigen::Matrix<double, C, 1>;

// Where the stages of a solve start, as rough fractions of its run (LinearSolverOptions::progress).
inline constexpr double kLinearSolveStart = 0.5;
inline constexpr double kResultsStart = 0.9;

// A condition's value as C numbers.
inline NodeVector<1> as_node_vector(double v) { return NodeVector<1>(v); }
inline NodeVector<3> as_node_vector(const Vec3& v) { return v; }

// Calls fn(p, nodes, node_count) for every quadrature point p of a cell, `nodes` being the
// local nodes whose shape functions its group involves.
template <class Fn>
void for_each_point(const CellPoints& q, Fn&& fn) {
  for (const auto& g : q.groups)
    for (int p = g.point_begin; p < g.point_begin + g.point_count; ++p)
      fn(p, q.nodes.data() + g.node_begin, g.node_count);
}

// k += modulus · Σ scale·r rᵀ over the cell's stabilisation rows, for each of the C unknowns
// per node (node-major).
template <int C>
void add_stabilization(const CellPoints& q, double modulus, Eigen::MatrixXd& k) {
  const Eigen::Index n = k.rows() / C;
  for (std::size_t t = 0; t < q.stabilization_scale.size(); ++t) {
    const Eigen::Map<const Eigen::VectorXd> r(q.stabilization_rows.data() + t * n, n);
    const Eigen::MatrixXd rr = (modulus * q.stabilization_scale[t]) * r * r.transpose();
    for (Eigen::Index a = 0; a < n; ++a)
      for (Eigen::Index b = 0; b < n; ++b)
        for (int d = 0; d < C; ++d) k(C * a + d, C * b + d) += rr(a, b);
  }
}

// The condition of every boundary tag, and which tags carry an essential one.
template <class Condition>
struct TagConditions {
  std::vector<const Condition*> of_tag;
  std::vector<char> essential, natural;
};

// Which kind of condition fixes the unknowns, and what is wrong when no boundary face has one.
template <class Condition>
struct Essential;
template <>
struct Essential<ScalarBoundaryCondition> {
  static constexpr auto kind = ScalarBoundaryCondition::Kind::dirichlet;
  static constexpr const char* missing =
      "no Dirichlet boundary condition on any boundary face: the solution is determined only "
      "up to a constant";
};
template <>
struct Essential<VectorBoundaryCondition> {
  static constexpr auto kind = VectorBoundaryCondition::Kind::displacement;
  static constexpr const char* missing =
      "no displacement boundary condition on any boundary face: the displacement is "
      "determined only up to a rigid motion";
};

template <class Condition>
bool has_essential(const TagConditions<Condition>& conditions) {
  return std::find(conditions.essential.begin(), conditions.essential.end(), 1) !=
         conditions.essential.end();
}

// Throws InputError (Essential::missing) when no boundary face carries an essential
// condition (require_essential; a piece of a mesh may have none of its own).
template <class Condition>
TagConditions<Condition> split_conditions(const PolyMesh& mesh,
                                          const std::map<std::string, Condition>& by_name,
                                          bool require_essential = true) {
  TagConditions<Condition> out;
  out.of_tag = conditions_per_tag(mesh, by_name);
  out.essential.assign(out.of_tag.size(), 0);
  out.natural.assign(out.of_tag.size(), 0);
  for (std::size_t t = 0; t < out.of_tag.size(); ++t)
    if (out.of_tag[t]) {
      out.essential[t] = out.of_tag[t]->kind == Essential<Condition>::kind;
      out.natural[t] = !out.essential[t];
    }
  if (require_essential && !has_essential(out)) throw InputError(Essential<Condition>::missing);
  return out;
}

// Starts cell c's local system: k and f zeroed for C unknowns per node (outer then
// internal nodes), the stiffness rule's points in work.stiffness, which it returns.
inline const CellPoints& begin_local(const FeSpace& space, Index c, int components,
                                     LocalWork& work) {
  const Eigen::Index n =
      components *
      (static_cast<Eigen::Index>(space.cell_nodes(c).size()) + space.internal_nodes());
  work.k.setZero(n, n);
  work.f.setZero(n);
  space.cell_points(c, Rule::stiffness, work.stiffness);
  return work.stiffness;
}

// Cell c's points of the load rule, once begin_local has put its stiffness points in work.
inline const CellPoints& load_points(const FeSpace& space, Index c, LocalWork& work) {
  if (space.load_is_stiffness(c)) return work.stiffness;
  space.cell_points(c, Rule::load, work.load);
  return work.load;
}

// A solved field: its space, the cells' internal rows (which recover the condensed internal
// unknowns) and the nodal unknowns. own_cell: in a distributed solve, the cells this rank
// evaluates (the others have no internal rows here); empty: all. node_owner: in a distributed
// solve, the rank owning each node; empty otherwise. in_pieces: the mesh is this rank's
// piece (LinearSolverOptions::piece_points), whose cells are all its own; nodes: over all
// ranks.
struct SolvedField {
  std::unique_ptr<FeSpace> space;
  InternalRows internal_rows;
  Eigen::VectorXd u;
  std::vector<char> own_cell;
  std::vector<int> node_owner;
  bool in_pieces = false;
  std::int64_t nodes = 0;
};

// Builds the space, assembles the local systems local(space, c, work) and the natural loads,
// fixes the nodes on essential tags (the lowest such tag of a node wins; values taken on
// the true boundary), solves. report.setup_seconds counts from `start` (the caller's
// per-cell data). Throws as split_conditions does. Everything before the linear solve is
// each rank's own work, the stage "assembly" (fem::stage).
template <int C, class Condition, class Local>
SolvedField solve_field(const PolyMesh& mesh, Space space_kind,
                        const std::map<std::string, Condition>& boundary,
                        const PointMap& to_true_boundary, const Local& local,
                        const LinearSolverOptions& options,
                        Clock::time_point start, LinearSolveReport& report) {
  Clock::time_point lap = start;
  const auto stage_seconds = [&lap] {
    const Clock::time_point now = Clock::now();
    const double s = std::chrono::duration<double>(now - lap).count();
    lap = now;
    return s;
  };
  SolvedField out;
  out.in_pieces = options.piece_points != nullptr;
  PieceNodes piece;
  bool essential = false;
  Distribution distribution;
  GlobalSystem system;
  std::vector<char> fixed;
  Eigen::VectorXd fixed_values;
  DistributedSystem rows;  // a distributed solve's
  double space_seconds = 0.0, assembly_seconds = 0.0, boundary_seconds = 0.0;
  stage("assembly", [&] {
    const TagConditions<Condition> conditions = split_conditions(mesh, boundary, !out.in_pieces);
    essential = has_essential(conditions);
    volmesh::report(options.progress, "assembly", 0.0);
    out.space = make_space(mesh, space_kind, to_true_boundary);
    const FeSpace& space = *out.space;
    if (options.cell_rank) {
      distribution = distribute(space, *options.cell_rank);
      out.own_cell = distribution.own_cell;
    }
    space_seconds = stage_seconds();
    system = assemble_cells(
        space, C, [&space, &local](Index c, LocalWork& work) { local(space, c, work); },
        &out.internal_rows, options.cell_rank ? &distribution.cells : nullptr);
    add_boundary_load(
        mesh, space, C, conditions.natural, to_true_boundary,
        [&](Index tag, const Vec3& at, double* values) {
          const auto& value = conditions.of_tag[tag]->value;
          const NodeVector<C> g = value ? as_node_vector(value(at)) : NodeVector<C>::Zero();
          std::copy(g.data(), g.data() + C, values);
        },
        system.rhs);
    assembly_seconds = stage_seconds();

    const Index nn = space.num_nodes();
    const std::vector<Index> essential_tag = lowest_marked_tag(mesh, space, conditions.essential);
    fixed.assign(C * std::size_t(nn), 0);
    fixed_values = Eigen::VectorXd::Zero(C * Eigen::Index(nn));
    for (Index n = 0; n < nn; ++n) {
      if (essential_tag[n] == kNoIndex) continue;
      std::fill_n(fixed.begin() + C * std::size_t(n), C, 1);
      const auto& value = conditions.of_tag[essential_tag[n]]->value;
      if (value)
        fixed_values.segment<C>(C * Eigen::Index(n)) =
            as_node_vector(value(on_true_boundary(to_true_boundary, space.node_point[n])));
    }
    boundary_seconds = stage_seconds();
    if (options.cell_rank)
      rows = distributed_rows(space, C, distribution, system, fixed, fixed_values, report);
  });
  if (out.in_pieces) {
    // The ranks' exchanges: the nodes they share, the fixed ones, the rows (fe_pieces.hpp).
    if (max_over_ranks(essential) == 0.0) throw InputError(Essential<Condition>::missing);
    stage("assembly", [&] {
      piece = piece_nodes(*out.space, options);
      agree_fixed(piece, C, fixed, fixed_values);
      boundary_seconds += stage_seconds();
      rows = piece_rows(*out.space, piece, C, system, fixed, fixed_values, report);
    });
    system = {};
  }
  volmesh::report(options.progress, "linear solve", kLinearSolveStart);
  if (out.in_pieces)
    out.u = solve_piece(piece, rows, fixed, fixed_values, options, report);
  else
    out.u = options.cell_rank
                ? solve_distributed(rows, fixed, fixed_values, options, report)
                : solve_spd_constrained(system.lower, system.rhs, fixed, fixed_values, options,
                                        report, {C, &out.space->node_point});
  out.node_owner = out.in_pieces ? std::move(piece.owner) : std::move(distribution.node_owner);
  out.nodes = out.in_pieces ? piece.count : out.space->num_nodes();
  report.setup_seconds += space_seconds + boundary_seconds;
  report.assembly_seconds += assembly_seconds;
  return out;
}

// The largest |u − u_h| at the nodes, in parallel; in a distributed solve each rank takes
// the nodes it owns and the ranks agree on the largest.
template <int C, class Exact>
double nodal_max_error(const SolvedField& field, const Exact& exact) {
  const bool distributed = !field.node_owner.empty();
  const int me = distributed ? rank() : 0;
  double mine = 0.0;
  stage("errors", [&] {
    mine = largest_of(field.space->num_nodes(), [&](Index n) {
      if (distributed && field.node_owner[n] != me) return 0.0;
      return (as_node_vector(exact(field.space->node_point[n])) -
              field.u.segment<C>(C * Eigen::Index(n)))
          .norm();
    });
  });
  return distributed ? max_over_ranks(mine) : mine;
}

// u_h and its gradient (row i: ∇ of component i) at a quadrature point.
template <int C>
struct PointValue {
  NodeVector<C> u;
  Eigen::Matrix<double, C, 3> gradient;
};

// fn(c, x, weight, value, result) at each point of cell c's pieces (CellPieces): u_h from
// the corner values, its gradient constant on a piece.
template <int C, class CellResult, class Fn>
void integrate_pieces(const CellPieces& q, const Eigen::VectorXd& local_u, Index c, const Fn& fn,
                      CellResult& r) {
  for (std::size_t i = 0; i < q.pieces.size(); ++i) {
    const CellPieces::Piece& piece = q.pieces[i];
    std::array<NodeVector<C>, 4> corner;
    PointValue<C> v;
    v.gradient.setZero();
    for (int k = 0; k < 4; ++k) {
      corner[k].setZero();
      for (int j = q.term_begin[4 * i + k]; j < q.term_begin[4 * i + k + 1]; ++j)
        corner[k] += q.coefficient[j] * local_u.segment<C>(C * q.node[j]);
      v.gradient += corner[k] * piece.affine.gradient[k].transpose();
    }
    const auto& x = piece.corners;
    for (const auto& p : q.rule) {
      const auto& l = p.barycentric;
      const Vec3 at = l[0] * x[0] + l[1] * x[1] + l[2] * x[2] + l[3] * x[3];
      const double w = piece.affine.volume * p.weight;
      v.u = l[0] * corner[0] + l[1] * corner[1] + l[2] * corner[2] + l[3] * corner[3];
      r.volume += w;
      fn(c, at, w, v, r);
    }
  }
}

// fn(c, x, weight, value, result) at each of cell c's points in q, u_h from its shape data.
template <int C, class CellResult, class Fn>
void integrate_points(const CellPoints& q, const Eigen::VectorXd& local_u, Index c, const Fn& fn,
                      CellResult& r) {
  for_each_point(q, [&](int p, const int* nodes, int count) {
    const double* value = q.value.data() + q.shape_begin[p];
    const Vec3* grad = q.gradient.data() + q.shape_begin[p];
    PointValue<C> v;
    v.u.setZero();
    v.gradient.setZero();
    for (int a = 0; a < count; ++a) {
      const NodeVector<C> ua = local_u.segment<C>(C * nodes[a]);
      v.u += value[a] * ua;
      v.gradient += ua * grad[a].transpose();
    }
    r.volume += q.weight[p];
    fn(c, q.x[p], q.weight[p], v, r);
  });
}

// Per cell, in parallel: fn(c, x, weight, value, result) at each point of the cell's
// `rule`, u_h from the solved field; result.volume sums the weights. Results in cell order.
// A distributed solve's ranks each integrate their own cells and add up the results (a cell's
// result comes from one rank, zeros from the others: the same numbers as one rank's).
template <int C, class CellResult, class Fn>
std::vector<CellResult> integrate_cells(const SolvedField& field, Rule rule, const Fn& fn) {
  std::vector<CellResult> out;
  stage("errors", [&] {
    out.resize(field.space->num_cells());
    for_each_cell(0, field.space->num_cells(), [&](Index c, LocalWork& work) {
      if (!field.own_cell.empty() && !field.own_cell[c]) return;
      Eigen::VectorXd local_u;
      cell_unknowns(*field.space, C, field.internal_rows, c, field.u, work, local_u);
      if (field.space->cell_pieces(c, rule, work.pieces))
        return integrate_pieces<C>(work.pieces, local_u, c, fn, out[c]);
      field.space->cell_points(c, rule, work.load);
      integrate_points<C>(work.load, local_u, c, fn, out[c]);
    });
  });
  if (!field.own_cell.empty() && !field.in_pieces) {
    static_assert(sizeof(CellResult) % sizeof(double) == 0, "a cell result is doubles only");
    sum_over_ranks(reinterpret_cast<double*>(out.data()),
                   out.size() * (sizeof(CellResult) / sizeof(double)));
  }
  return out;
}

}  // namespace volmesh::fem::detail
