#pragma once
// Global systems from cell-local ones. Local systems are computed in parallel, a bounded
// batch of cells at a time, then added into the matrix column by column in cell order, so
// every entry is summed in the same order for any thread count: the same bytes.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>

#include "fe_space.hpp"

namespace volmesh::fem::detail {

// Scratch of one thread's local computations.
struct LocalWork {
  CellPoints stiffness, load;
  // Over the cell's outer then internal nodes, `components` unknowns per node (node-major).
  Eigen::MatrixXd k;
  Eigen::VectorXd f;
};

// Fills work.k and work.f for cell c.
using LocalSystem = std::function<void(Index c, LocalWork& work)>;

struct GlobalSystem {
  Eigen::SparseMatrix<double> lower;  // the lower triangle, which is what solve_spd reads
  Eigen::VectorXd rhs;
};

GlobalSystem assemble_cells(const FeSpace& space, int components, const LocalSystem& local);

// Static condensation of the trailing `internal` unknowns: afterwards the leading block of
// (k, f) is the condensed system of the others.
void condense(Eigen::MatrixXd& k, Eigen::VectorXd& f, int internal);

// Cell c's unknowns over its outer then internal nodes: the outer ones from the global
// solution, the internal ones recovered from the local system.
void cell_unknowns(const FeSpace& space, int components, const LocalSystem& local, Index c,
                   const Eigen::VectorXd& global, LocalWork& work, Eigen::VectorXd& out);

// Calls fn(c, work) for the cells c in [begin, end), in parallel, each thread with its own work.
void for_each_cell(Index begin, Index end, const std::function<void(Index c, LocalWork& work)>& fn);

}  // namespace volmesh::fem::detail
