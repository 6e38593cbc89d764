#pragma once
// Global systems from cell-local ones. Local systems are computed in parallel, a bounded
// batch of cells at a time, then added into the matrix column by column in cell order, so
// every entry is summed in the same order for any thread count: the same bytes.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <vector>

#include "fe_space.hpp"

namespace volmesh::fem::detail {

// Scratch of one thread's local computations.
struct LocalWork {
  CellPoints stiffness, load;
  CellPieces pieces;
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

// What recovers a cell's condensed internal unknowns from its outer ones: the internal rows
// of its local system (k's last rows over all the cell's unknowns, then f's last entries),
// kept by the assembly so that no local system is computed twice.
struct InternalRows {
  std::vector<std::size_t> offset;  // per cell into values, then the end
  std::vector<double> values;
};

// `internal_rows`, when given, receives the internal rows (none for a space without
// internal nodes). `cells`, when given (increasing), are the only cells assembled: the
// matrix then holds their entries only (a rank's rows are whole when `cells` contains every
// cell touching them) and only they get internal rows.
GlobalSystem assemble_cells(const FeSpace& space, int components, const LocalSystem& local,
                            InternalRows* internal_rows = nullptr,
                            const std::vector<Index>* cells = nullptr);

// Static condensation of the trailing `internal` unknowns: afterwards the leading block of
// (k, f) is the condensed system of the others.
void condense(Eigen::MatrixXd& k, Eigen::VectorXd& f, int internal);

// Cell c's unknowns over its outer then internal nodes: the outer ones from the global
// solution, the internal ones recovered from the internal rows the assembly kept.
void cell_unknowns(const FeSpace& space, int components, const InternalRows& rows, Index c,
                   const Eigen::VectorXd& global, LocalWork& work, Eigen::VectorXd& out);

// Calls fn(c, work) for the cells c in [begin, end), in parallel, each thread with its own work.
void for_each_cell(Index begin, Index end, const std::function<void(Index c, LocalWork& work)>& fn);

}  // namespace volmesh::fem::detail
