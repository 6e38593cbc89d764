#include "fe_pieces.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "petsc_solve.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/fem/parallel.hpp"

namespace volmesh::fem::detail {
namespace {

Index owned_node(const PieceNodes& nodes, double number) {
  const std::int64_t key = static_cast<std::int64_t>(number);
  const auto it = std::lower_bound(nodes.owned.begin(), nodes.owned.end(),
                                   std::pair<std::int64_t, Index>(key, 0));
  if (it == nodes.owned.end() || it->first != key)
    throw std::runtime_error("pieces: point " + std::to_string(key) + " is not its owner's");
  return it->second;
}

// The first of each rank's `mine` in rank order: the sum of the lower ranks'.
std::int64_t first_after_lower_ranks(std::int64_t mine, std::int64_t* total) {
  const double count = static_cast<double>(mine);
  const std::vector<double> all = gather_to_all(&count, 1);
  std::int64_t first = 0;
  for (int r = 0; r < rank(); ++r) first += static_cast<std::int64_t>(all[r]);
  *total = 0;
  for (const double n : all) *total += static_cast<std::int64_t>(n);
  return first;
}

}  // namespace

PieceNodes piece_nodes(const FeSpace& space, const LinearSolverOptions& options) {
  const std::vector<std::int64_t>& points = *options.piece_points;
  const std::vector<int>& owner = *options.piece_owner;
  PieceNodes out;
  out.global.assign(space.num_nodes(), -1);
  out.owner.assign(space.num_nodes(), -1);
  for (std::size_t p = 0; p < space.point_node.size(); ++p) {
    const Index n = space.point_node[p];
    if (n == kNoIndex) continue;
    out.global[n] = points[p];
    out.owner[n] = owner[p];
  }
  if (std::find(out.owner.begin(), out.owner.end(), -1) != out.owner.end())
    throw InputError("a mesh in pieces takes the spaces with nodes at the vertices only (p1, q1, "
                     "polyhedral): use --partition metis");
  for (Index n = 0; n < space.num_nodes(); ++n)
    if (out.owner[n] == rank()) out.owned.emplace_back(out.global[n], n);
  std::sort(out.owned.begin(), out.owned.end());
  first_after_lower_ranks(static_cast<std::int64_t>(out.owned.size()), &out.count);
  return out;
}

std::vector<double> ask_owners(const PieceNodes& nodes, int width,
                               const std::function<void(Index, double*)>& answer) {
  const int me = rank();
  std::vector<double> out(nodes.global.size() * width);
  std::vector<std::vector<double>> questions(ranks());
  std::vector<std::vector<Index>> asked(ranks());
  for (std::size_t n = 0; n < nodes.global.size(); ++n) {
    const int owner = nodes.owner[n];
    if (owner == me) {
      answer(static_cast<Index>(n), out.data() + n * width);
    } else {
      questions[owner].push_back(static_cast<double>(nodes.global[n]));
      asked[owner].push_back(static_cast<Index>(n));
    }
  }
  const std::vector<std::vector<double>> received = exchange(questions);
  std::vector<std::vector<double>> replies(ranks());
  for (int r = 0; r < ranks(); ++r) {
    replies[r].resize(received[r].size() * width);
    for (std::size_t q = 0; q < received[r].size(); ++q)
      answer(owned_node(nodes, received[r][q]), replies[r].data() + q * width);
  }
  const std::vector<std::vector<double>> answers = exchange(replies);
  for (int r = 0; r < ranks(); ++r)
    for (std::size_t q = 0; q < asked[r].size(); ++q)
      std::copy_n(answers[r].data() + q * width, width, out.data() + asked[r][q] * width);
  return out;
}

void agree_fixed(const PieceNodes& nodes, int components, std::vector<char>& fixed,
                 Eigen::VectorXd& fixed_values) {
  const int me = rank(), c = components;
  // What each rank finds goes to the owners, which take their own or the lowest rank's.
  std::vector<std::vector<double>> found(ranks());
  for (std::size_t n = 0; n < nodes.global.size(); ++n) {
    if (nodes.owner[n] == me || !fixed[c * n]) continue;
    std::vector<double>& to = found[nodes.owner[n]];
    to.push_back(static_cast<double>(nodes.global[n]));
    for (int d = 0; d < c; ++d) to.push_back(fixed_values[c * n + d]);
  }
  const std::vector<std::vector<double>> received = exchange(found);
  for (const std::vector<double>& from : received)
    for (std::size_t k = 0; k < from.size(); k += c + 1) {
      const Index n = owned_node(nodes, from[k]);
      if (fixed[c * n]) continue;
      for (int d = 0; d < c; ++d) {
        fixed[c * n + d] = 1;
        fixed_values[c * n + d] = from[k + 1 + d];
      }
    }
  // Then every rank takes the owners' verdicts: (fixed, value per unknown).
  const std::vector<double> verdict = ask_owners(nodes, c + 1, [&](Index n, double* out) {
    out[0] = fixed[c * n];
    for (int d = 0; d < c; ++d) out[1 + d] = fixed_values[c * n + d];
  });
  for (std::size_t n = 0; n < nodes.global.size(); ++n)
    for (int d = 0; d < c; ++d) {
      fixed[c * n + d] = verdict[(c + 1) * n] != 0.0;
      fixed_values[c * n + d] = verdict[(c + 1) * n + 1 + d];
    }
}

DistributedSystem piece_rows(const FeSpace& space, const PieceNodes& nodes, int components,
                             const GlobalSystem& system, const std::vector<char>& fixed,
                             const Eigen::VectorXd& fixed_values, LinearSolveReport& report) {
  const auto start = std::chrono::steady_clock::now();
  const int me = rank(), c = components;
  const Index ndof = static_cast<Index>(fixed.size());

  // The free unknowns the rank owns, numbered after the lower ranks' in node order.
  DistributedSystem out;
  out.global.assign(ndof, kNoIndex);
  OwnedRows& rows = out.rows;
  std::int64_t owned = 0;
  for (Index dof = 0; dof < ndof; ++dof)
    owned += nodes.owner[dof / c] == me && !fixed[dof];
  std::int64_t total = 0;
  const std::int64_t first = first_after_lower_ranks(owned, &total);
  if (total > kMaxIndex) throw InputError("mesh: more unknowns than 32-bit indices allow");
  Index next = static_cast<Index>(first);
  for (Index dof = 0; dof < ndof; ++dof)
    if (nodes.owner[dof / c] == me && !fixed[dof]) {
      out.global[dof] = next++;
      if (c == 3) rows.coordinates.push_back(space.node_point[dof / 3][dof % 3]);
    }
  const std::vector<double> numbers = ask_owners(nodes, c, [&](Index n, double* v) {
    for (int d = 0; d < c; ++d) v[d] = out.global[c * n + d];
  });
  for (Index dof = 0; dof < ndof; ++dof)
    if (!fixed[dof]) out.global[dof] = static_cast<Index>(numbers[dof]);

  // A row as (global column, value) entries, the fixed columns moved to the right-hand side.
  const Eigen::SparseMatrix<double, Eigen::RowMajor> full =
      system.lower.selfadjointView<Eigen::Lower>();
  std::vector<std::pair<Index, double>> row;
  const auto local_row = [&](Index dof) {
    return eliminated_row(full, system.rhs, dof, fixed, fixed_values, out.global, row);
  };

  // The partial rows of shared nodes go to their owners as (row, column, value) entries, the
  // right-hand side as column -1.
  constexpr Index kRightHandSide = -1;
  std::vector<std::vector<double>> partial(ranks());
  for (Index dof = 0; dof < ndof; ++dof) {
    const int owner = nodes.owner[dof / c];
    if (fixed[dof] || owner == me) continue;
    const double rhs = local_row(dof), at = out.global[dof];
    std::vector<double>& to = partial[owner];
    for (const auto& [col, value] : row) to.insert(to.end(), {at, double(col), value});
    to.insert(to.end(), {at, double(kRightHandSide), rhs});
  }
  std::vector<std::tuple<Index, Index, double>> received;
  for (const std::vector<double>& from : exchange(partial))
    for (std::size_t k = 0; k < from.size(); k += 3)
      received.emplace_back(static_cast<Index>(from[k]), static_cast<Index>(from[k + 1]), from[k + 2]);
  partial = {};
  // By row, the senders in rank order within a row: the same sums on every run.
  std::stable_sort(received.begin(), received.end(), [](const auto& a, const auto& b) {
    return std::get<0>(a) < std::get<0>(b);
  });

  // The owned rows whole: this rank's part, then the others' in rank order, by column.
  rows.distributed = true;
  rows.first = static_cast<Index>(first);
  rows.global = static_cast<Index>(total);
  rows.block_size = c;
  rows.rhs.resize(owned);
  std::size_t k = 0;
  for (Index dof = 0; dof < ndof; ++dof) {
    if (fixed[dof] || nodes.owner[dof / c] != me) continue;
    const Index at = out.global[dof];
    double rhs = local_row(dof);
    for (; k < received.size() && std::get<0>(received[k]) == at; ++k) {
      const auto& [r, col, value] = received[k];
      if (col == kRightHandSide)
        rhs += value;
      else
        row.emplace_back(col, value);
    }
    std::stable_sort(row.begin(), row.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t e = 0; e < row.size(); ++e) {
      if (e > 0 && row[e].first == row[e - 1].first) {
        rows.values.back() += row[e].second;
        continue;
      }
      rows.columns.push_back(row[e].first);
      rows.values.push_back(row[e].second);
    }
    rows.offsets.push_back(static_cast<Index>(rows.columns.size()));
    rows.rhs[at - first] = rhs;
  }
  report.unknowns = rows.global;
  report.assembly_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

Eigen::VectorXd solve_piece(const PieceNodes& nodes, const DistributedSystem& system,
                            const std::vector<char>& fixed, const Eigen::VectorXd& fixed_values,
                            const LinearSolverOptions& options, LinearSolveReport& report) {
  const Eigen::VectorXd mine = petsc_solve_spd(system.rows, options, report);
  const auto gathering = std::chrono::steady_clock::now();
  const int c = system.rows.block_size;
  const auto value = [&](Index dof) {
    return fixed[dof] ? fixed_values[dof] : mine[system.global[dof] - system.rows.first];
  };
  const std::vector<double> at_nodes = ask_owners(nodes, c, [&](Index n, double* v) {
    for (int d = 0; d < c; ++d) v[d] = value(c * n + d);
  });
  report.solve_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - gathering).count();
  return Eigen::Map<const Eigen::VectorXd>(at_nodes.data(), static_cast<Eigen::Index>(at_nodes.size()));
}

}  // namespace volmesh::fem::detail
