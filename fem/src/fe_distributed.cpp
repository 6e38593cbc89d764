#include "fe_distributed.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <utility>

#include "petsc_solve.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/fem/parallel.hpp"

namespace volmesh::fem::detail {

Distribution distribute(const FeSpace& space, const std::vector<Index>& cell_rank) {
  const int me = rank(), count = ranks();
  if (cell_rank.size() != std::size_t(space.num_cells()))
    throw InputError("the partition has " + std::to_string(cell_rank.size()) +
                     " entries for " + std::to_string(space.num_cells()) + " cells");
  Distribution d;
  d.node_owner.assign(space.num_nodes(), count);
  d.own_cell.assign(space.num_cells(), 0);
  for (Index c = 0; c < space.num_cells(); ++c) {
    const Index r = cell_rank[c];
    if (r < 0 || r >= count)
      throw InputError("the partition gives cell " + std::to_string(c) + " to part " +
                       std::to_string(r) + ", and the run has " + std::to_string(count) +
                       " ranks");
    d.own_cell[c] = r == me;
    for (Index n : space.cell_nodes(c)) d.node_owner[n] = std::min<int>(d.node_owner[n], r);
  }
  for (Index c = 0; c < space.num_cells(); ++c) {
    const auto nodes = space.cell_nodes(c);
    if (std::any_of(nodes.begin(), nodes.end(), [&](Index n) { return d.node_owner[n] == me; }))
      d.cells.push_back(c);
  }
  return d;
}

double eliminated_row(const Eigen::SparseMatrix<double, Eigen::RowMajor>& full,
                      const Eigen::VectorXd& rhs, Index dof, const std::vector<char>& fixed,
                      const Eigen::VectorXd& fixed_values, const std::vector<Index>& global,
                      std::vector<std::pair<Index, double>>& row) {
  row.clear();
  double out = rhs[dof];
  for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(full, dof); it; ++it) {
    const Index col = static_cast<Index>(it.col());
    if (fixed[col])
      out -= it.value() * fixed_values[col];
    else
      row.emplace_back(global[col], it.value());
  }
  return out;
}

DistributedSystem distributed_rows(const FeSpace& space, int components,
                                   const Distribution& distribution, const GlobalSystem& system,
                                   const std::vector<char>& fixed,
                                   const Eigen::VectorXd& fixed_values, LinearSolveReport& report) {
  const auto start = std::chrono::steady_clock::now();
  const int me = rank(), count = ranks();
  const Index nn = space.num_nodes();
  const auto owner_of = [&](Index dof) { return distribution.node_owner[dof / components]; };

  // Global numbering of the free unknowns: rank by rank, in node order within a rank.
  const Index ndof = nn * components;
  std::vector<std::int64_t> first(count + 1, 0);
  for (Index dof = 0; dof < ndof; ++dof)
    if (!fixed[dof]) ++first[owner_of(dof) + 1];
  for (int r = 0; r < count; ++r) first[r + 1] += first[r];
  if (first[count] > kMaxIndex)
    throw InputError("mesh: more unknowns than 32-bit indices allow");
  DistributedSystem out;
  out.global.assign(ndof, kNoIndex);
  {
    std::vector<std::int64_t> next(first.begin(), first.end() - 1);
    for (Index dof = 0; dof < ndof; ++dof)
      if (!fixed[dof]) out.global[dof] = static_cast<Index>(next[owner_of(dof)]++);
  }

  // This rank's whole rows, fixed columns moved to the right-hand side.
  const Eigen::SparseMatrix<double, Eigen::RowMajor> full =
      system.lower.selfadjointView<Eigen::Lower>();
  OwnedRows& rows = out.rows;
  rows.distributed = true;
  rows.first = static_cast<Index>(first[me]);
  rows.global = static_cast<Index>(first[count]);
  rows.block_size = components;
  rows.rhs.resize(first[me + 1] - first[me]);
  std::vector<std::pair<Index, double>> row;
  Index local = 0;
  for (Index dof = 0; dof < ndof; ++dof) {
    if (fixed[dof] || owner_of(dof) != me) continue;
    const double rhs =
        eliminated_row(full, system.rhs, dof, fixed, fixed_values, out.global, row);
    std::sort(row.begin(), row.end());
    for (const auto& [col, value] : row) {
      rows.columns.push_back(col);
      rows.values.push_back(value);
    }
    rows.offsets.push_back(static_cast<Index>(rows.columns.size()));
    rows.rhs[local++] = rhs;
    if (components == 3) rows.coordinates.push_back(space.node_point[dof / 3][dof % 3]);
  }
  report.unknowns = rows.global;
  report.assembly_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

Eigen::VectorXd solve_distributed(const DistributedSystem& system, const std::vector<char>& fixed,
                                  const Eigen::VectorXd& fixed_values,
                                  const LinearSolverOptions& options, LinearSolveReport& report) {
  const Eigen::VectorXd mine = petsc_solve_spd(system.rows, options, report);
  const auto gathering = std::chrono::steady_clock::now();
  const std::vector<double> all = gather_to_all(mine.data(), std::size_t(mine.size()));
  const Index ndof = static_cast<Index>(fixed.size());
  Eigen::VectorXd u(ndof);
  for (Index dof = 0; dof < ndof; ++dof)
    u[dof] = fixed[dof] ? fixed_values[dof] : all[system.global[dof]];
  report.solve_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - gathering).count();
  return u;
}

}  // namespace volmesh::fem::detail
