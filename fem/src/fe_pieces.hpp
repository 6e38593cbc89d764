#pragma once
// A finite-element solve over a mesh held in pieces, one per rank, no rank holding the whole
// (LinearSolverOptions::piece_points). Each rank assembles its own cells. A node on a piece
// boundary belongs to the lowest rank whose cells use it: the other ranks send it their
// partial rows, so that it hands PETSc whole rows, and ask it for what they need of the
// node (whether it is fixed, its unknowns' numbers, the solution). Only vertex nodes (p1, q1,
// polyhedral): a node is known on every rank by its point's number.
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "fe_distributed.hpp"
#include "fe_space.hpp"
#include "volmesh/fem/linear_solver.hpp"

namespace volmesh::fem::detail {

struct PieceNodes {
  std::vector<std::int64_t> global;  // per node: its point's number over all ranks
  std::vector<int> owner;            // per node
  std::vector<std::pair<std::int64_t, Index>> owned;  // (number, node) of the owned nodes, sorted
  std::int64_t count = 0;                             // nodes over all ranks
};

// Throws InputError for a space with nodes off the vertices (p2). Collective.
PieceNodes piece_nodes(const FeSpace& space, const LinearSolverOptions& options);

// `width` numbers about every node: answer(node, out) on the node's owner, asked by the other
// ranks holding it. Collective.
std::vector<double> ask_owners(const PieceNodes& nodes, int width,
                               const std::function<void(Index, double*)>& answer);

// Makes `fixed` (per unknown, C per node) and `fixed_values` agree over the ranks: a node is
// fixed when any rank holding it finds it on a face with an essential condition (a rank may
// not hold that face), its values its owner's or else the lowest such rank's. Collective.
void agree_fixed(const PieceNodes& nodes, int components, std::vector<char>& fixed,
                 Eigen::VectorXd& fixed_values);

// This rank's whole rows of the free unknowns it owns, from every rank's partial rows of
// `system` (assembled over its own cells), the fixed unknowns moved to the right-hand side;
// `global` numbers every free unknown of the piece. Collective; counts as assembly.
DistributedSystem piece_rows(const FeSpace& space, const PieceNodes& nodes, int components,
                             const GlobalSystem& system, const std::vector<char>& fixed,
                             const Eigen::VectorXd& fixed_values, LinearSolveReport& report);

// The solution at every node of the piece. Collective. Fills report as solve_spd does.
Eigen::VectorXd solve_piece(const PieceNodes& nodes, const DistributedSystem& system,
                            const std::vector<char>& fixed, const Eigen::VectorXd& fixed_values,
                            const LinearSolverOptions& options, LinearSolveReport& report);

}  // namespace volmesh::fem::detail
