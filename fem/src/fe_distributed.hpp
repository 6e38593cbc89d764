#pragma once
// A finite-element solve spread over the ranks (PETSc on PETSC_COMM_WORLD). Every rank holds
// the whole mesh and builds the same space; rank r owns the cells of part r and the nodes
// whose lowest-ranked cell is one of them (a node on a part boundary belongs to the lowest
// part among the cells using it). Each rank computes the local systems of the cells touching
// its nodes (its own cells and one layer of its neighbours'), so its rows are whole without
// any exchange of matrix values, and hands PETSc only those rows, the fixed unknowns
// eliminated: the preallocation is exact and no value goes to another rank. The solution is
// then gathered to every rank, and each rank evaluates its own cells.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <utility>
#include <vector>

#include "fe_assembly.hpp"
#include "petsc_solve.hpp"
#include "volmesh/fem/linear_solver.hpp"

namespace volmesh::fem::detail {

struct Distribution {
  std::vector<Index> cells;    // the cells this rank assembles, increasing
  std::vector<char> own_cell;  // per cell: in this rank's part
  std::vector<int> node_owner;  // per node: the rank owning it
};

// Throws InputError when cell_rank does not give every cell a rank in [0, ranks).
Distribution distribute(const FeSpace& space, const std::vector<Index>& cell_rank);

// This rank's rows of a system whose owned rows `system` holds whole (assembled over
// distribution.cells), the `fixed` unknowns taking `fixed_values`, and the global number of
// every free unknown. This rank's work alone; counts as assembly in report. Throws
// InputError past 32-bit indices.
struct DistributedSystem {
  OwnedRows rows;
  std::vector<Index> global;  // per unknown; kNoIndex for a fixed one
};
DistributedSystem distributed_rows(const FeSpace& space, int components,
                                   const Distribution& distribution, const GlobalSystem& system,
                                   const std::vector<char>& fixed,
                                   const Eigen::VectorXd& fixed_values, LinearSolveReport& report);

// Row `dof` of the symmetric system `full` as (global column, value) entries in `row`, by the
// `global` numbers of the free unknowns; the fixed columns go to the right-hand side: returns
// rhs[dof] minus them.
double eliminated_row(const Eigen::SparseMatrix<double, Eigen::RowMajor>& full,
                      const Eigen::VectorXd& rhs, Index dof, const std::vector<char>& fixed,
                      const Eigen::VectorXd& fixed_values, const std::vector<Index>& global,
                      std::vector<std::pair<Index, double>>& row);

// The whole solution on every rank. Collective. Fills report as solve_spd does.
Eigen::VectorXd solve_distributed(const DistributedSystem& system, const std::vector<char>& fixed,
                                  const Eigen::VectorXd& fixed_values,
                                  const LinearSolverOptions& options, LinearSolveReport& report);

}  // namespace volmesh::fem::detail
