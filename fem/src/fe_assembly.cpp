#include "fe_assembly.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "volmesh/core/errors.hpp"

namespace volmesh::fem::detail {
namespace {

// Local matrices held at once: bounds the memory of a batch (32 MB of doubles).
constexpr std::size_t kBatchEntries = std::size_t(1) << 22;

// The assembled cells: a given increasing list, or all cells.
struct CellList {
  const std::vector<Index>* list;
  Index count;
  Index size() const { return list ? static_cast<Index>(list->size()) : count; }
  Index operator[](Index k) const { return list ? (*list)[k] : k; }
};

struct Csr {
  std::vector<Index> offsets;
  std::vector<Index> items;
};

// Node → the assembled cells using it, cells in increasing order.
Csr node_cells(const FeSpace& space, const CellList& cells) {
  Csr r;
  r.offsets.assign(space.num_nodes() + 1, 0);
  for (Index k = 0; k < cells.size(); ++k)
    for (Index n : space.cell_nodes(cells[k])) ++r.offsets[n + 1];
  for (Index n = 0; n < space.num_nodes(); ++n) r.offsets[n + 1] += r.offsets[n];
  r.items.resize(r.offsets.back());
  std::vector<Index> fill(r.offsets.begin(), r.offsets.end() - 1);
  for (Index k = 0; k < cells.size(); ++k)
    for (Index n : space.cell_nodes(cells[k])) r.items[fill[n]++] = cells[k];
  return r;
}

// For each node j, the sorted nodes i >= j sharing an assembled cell with it (j included).
Csr lower_node_pattern(const FeSpace& space, const Csr& cells_of) {
  const Index nn = space.num_nodes();
  Csr r;
  r.offsets.assign(nn + 1, 0);
  // A per-thread stamp array marks the nodes already gathered for node j.
  tbb::enumerable_thread_specific<std::vector<Index>> stamps(
      [nn] { return std::vector<Index>(nn, kNoIndex); });
  // Node j itself first, so that a node no assembled cell touches keeps its diagonal.
  const auto gather = [&](Index j, std::vector<Index>& stamp, auto&& emit) {
    stamp[j] = j;
    emit(j);
    for (Index k = cells_of.offsets[j]; k < cells_of.offsets[j + 1]; ++k)
      for (Index i : space.cell_nodes(cells_of.items[k]))
        if (i >= j && stamp[i] != j) {
          stamp[i] = j;
          emit(i);
        }
  };
  tbb::parallel_for(tbb::blocked_range<Index>(0, nn), [&](const tbb::blocked_range<Index>& range) {
    auto& stamp = stamps.local();
    for (Index j = range.begin(); j != range.end(); ++j) {
      Index count = 0;
      gather(j, stamp, [&](Index) { ++count; });
      r.offsets[j + 1] = count;
    }
  });
  for (Index j = 0; j < nn; ++j) {
    if (static_cast<std::int64_t>(r.offsets[j]) + r.offsets[j + 1] > kMaxIndex)
      throw InputError("mesh: the matrix has more entries than 32-bit indices allow");
    r.offsets[j + 1] += r.offsets[j];
  }
  r.items.resize(r.offsets[nn]);
  // Second pass with fresh stamps: node j was stamped with j in the first pass.
  for (auto& stamp : stamps) std::fill(stamp.begin(), stamp.end(), kNoIndex);
  tbb::parallel_for(tbb::blocked_range<Index>(0, nn), [&](const tbb::blocked_range<Index>& range) {
    auto& stamp = stamps.local();
    for (Index j = range.begin(); j != range.end(); ++j) {
      Index* out = r.items.data() + r.offsets[j];
      Index count = 0;
      gather(j, stamp, [&](Index i) { out[count++] = i; });
      std::sort(out, out + count);
    }
  });
  return r;
}

// The lower triangle's structure over all unknowns (node-major), values zero.
Eigen::SparseMatrix<double> lower_pattern(const Csr& nodes, Index num_nodes, int components) {
  const std::int64_t ndof = std::int64_t(num_nodes) * components;
  std::vector<std::int64_t> offsets(ndof + 1, 0);
  for (Index j = 0; j < num_nodes; ++j) {
    const std::int64_t others = nodes.offsets[j + 1] - nodes.offsets[j] - 1;
    for (int c = 0; c < components; ++c)
      offsets[std::int64_t(j) * components + c + 1] = others * components + (components - c);
  }
  for (std::int64_t d = 0; d < ndof; ++d) offsets[d + 1] += offsets[d];
  if (offsets[ndof] > kMaxIndex)
    throw InputError("mesh: the matrix has more entries than 32-bit indices allow");

  Eigen::SparseMatrix<double> a(ndof, ndof);
  a.resizeNonZeros(static_cast<Index>(offsets[ndof]));
  int* outer = a.outerIndexPtr();
  int* inner = a.innerIndexPtr();
  for (std::int64_t d = 0; d <= ndof; ++d) outer[d] = static_cast<int>(offsets[d]);
  std::fill(a.valuePtr(), a.valuePtr() + offsets[ndof], 0.0);
  tbb::parallel_for(tbb::blocked_range<Index>(0, num_nodes),
                    [&](const tbb::blocked_range<Index>& r) {
                      for (Index j = r.begin(); j != r.end(); ++j)
                        for (int c = 0; c < components; ++c) {
                          int* out = inner + outer[std::int64_t(j) * components + c];
                          for (Index k = nodes.offsets[j]; k < nodes.offsets[j + 1]; ++k) {
                            const Index i = nodes.items[k];
                            for (int d = i == j ? c : 0; d < components; ++d)
                              *out++ = static_cast<int>(std::int64_t(i) * components + d);
                          }
                        }
                    });
  return a;
}

}  // namespace

void condense(Eigen::MatrixXd& k, Eigen::VectorXd& f, int internal) {
  if (internal == 0) return;
  const Eigen::Index outer = k.rows() - internal;
  const Eigen::LLT<Eigen::MatrixXd> kii(k.bottomRightCorner(internal, internal));
  const Eigen::MatrixXd x = kii.solve(k.bottomLeftCorner(internal, outer));  // Kii⁻¹ Kio
  const Eigen::VectorXd y = kii.solve(f.tail(internal));
  k.topLeftCorner(outer, outer).noalias() -= k.topRightCorner(outer, internal) * x;
  f.head(outer).noalias() -= k.topRightCorner(outer, internal) * y;
}

void cell_unknowns(const FeSpace& space, int components, const InternalRows& rows, Index c,
                   const Eigen::VectorXd& global, LocalWork& work, Eigen::VectorXd& out) {
  const auto nodes = space.cell_nodes(c);
  const Eigen::Index outer = static_cast<Eigen::Index>(nodes.size()) * components;
  const int internal = space.internal_nodes() * components;
  out.resize(outer + internal);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (int i = 0; i < components; ++i)
      out[a * components + i] = global[std::int64_t(nodes[a]) * components + i];
  if (internal == 0) return;
  // k and f as the cell's local system left them in the rows read below.
  const Eigen::Index n = outer + internal;
  const double* kept = rows.values.data() + rows.offset[c];
  work.k.resize(n, n);
  work.k.bottomRows(internal) = Eigen::Map<const Eigen::MatrixXd>(kept, internal, n);
  work.f.resize(n);
  work.f.tail(internal) = Eigen::Map<const Eigen::VectorXd>(kept + internal * n, internal);
  const Eigen::VectorXd rhs =
      work.f.tail(internal) - work.k.bottomLeftCorner(internal, outer) * out.head(outer);
  out.tail(internal) = work.k.bottomRightCorner(internal, internal).llt().solve(rhs);
}

void for_each_cell(Index begin, Index end,
                   const std::function<void(Index c, LocalWork& work)>& fn) {
  tbb::enumerable_thread_specific<LocalWork> works;
  tbb::parallel_for(tbb::blocked_range<Index>(begin, end), [&](const tbb::blocked_range<Index>& r) {
    LocalWork& work = works.local();
    for (Index c = r.begin(); c != r.end(); ++c) fn(c, work);
  });
}

GlobalSystem assemble_cells(const FeSpace& space, int components, const LocalSystem& local,
                            InternalRows* internal_rows, const std::vector<Index>* subset) {
  const CellList cells{subset, space.num_cells()};
  const Index nn = space.num_nodes();
  const Index nc = cells.size();
  if (std::int64_t(nn) * components > kMaxIndex)
    throw InputError("mesh: more unknowns than 32-bit indices allow");
  const Index ndof = nn * components;
  GlobalSystem system;
  system.lower = lower_pattern(lower_node_pattern(space, node_cells(space, cells)), nn, components);
  system.rhs = Eigen::VectorXd::Zero(ndof);
  const int* outer = system.lower.outerIndexPtr();
  const int* inner = system.lower.innerIndexPtr();
  double* values = system.lower.valuePtr();

  const int internal = space.internal_nodes() * components;
  const auto size_of = [&](Index c) {
    return std::size_t(space.cell_nodes(c).size()) * components;
  };
  InternalRows* const keep = internal > 0 ? internal_rows : nullptr;
  if (keep) {
    // Every cell has its slot; a cell outside the subset an empty one.
    std::vector<char> assembled(space.num_cells(), 0);
    for (Index k = 0; k < nc; ++k) assembled[cells[k]] = 1;
    keep->offset.assign(1, 0);
    for (Index c = 0; c < space.num_cells(); ++c)
      keep->offset.push_back(keep->offset.back() +
                             (assembled[c] ? internal * (size_of(c) + internal + 1) : 0));
    keep->values.resize(keep->offset.back());
  }
  // Column ranges, one per thread: each column is summed by one thread in cell order.
  const int ranges = std::max(1, tbb::this_task_arena::max_concurrency());
  std::vector<std::size_t> offset, f_offset;  // per cell of the batch, into k_batch, f_batch
  std::vector<double> k_batch, f_batch;
  for (Index begin = 0; begin < nc;) {
    Index end = begin;
    offset.assign(1, 0);
    f_offset.assign(1, 0);
    while (end < nc && (end == begin || offset.back() + size_of(cells[end]) *
                                                             size_of(cells[end]) <=
                                            kBatchEntries)) {
      offset.push_back(offset.back() + size_of(cells[end]) * size_of(cells[end]));
      f_offset.push_back(f_offset.back() + size_of(cells[end]));
      ++end;
    }
    k_batch.resize(offset.back());
    f_batch.resize(f_offset.back());

    for_each_cell(begin, end, [&](Index k, LocalWork& work) {
      const Index c = cells[k];
      local(c, work);
      if (keep) {
        const Eigen::Index n = work.k.rows();
        double* rows = keep->values.data() + keep->offset[c];
        Eigen::Map<Eigen::MatrixXd>(rows, internal, n) = work.k.bottomRows(internal);
        Eigen::Map<Eigen::VectorXd>(rows + internal * n, internal) = work.f.tail(internal);
      }
      condense(work.k, work.f, internal);
      const Eigen::Index m = static_cast<Eigen::Index>(size_of(c));
      Eigen::Map<Eigen::MatrixXd>(k_batch.data() + offset[k - begin], m, m) =
          work.k.topLeftCorner(m, m);
      Eigen::Map<Eigen::VectorXd>(f_batch.data() + f_offset[k - begin], m) = work.f.head(m);
    });

    tbb::parallel_for(0, ranges, [&](int part) {
      const Index lo = static_cast<Index>(std::int64_t(ndof) * part / ranges);
      const Index hi = static_cast<Index>(std::int64_t(ndof) * (part + 1) / ranges);
      std::vector<Index> dof;
      for (Index k = begin; k < end; ++k) {
        const Index c = cells[k];
        const auto nodes = space.cell_nodes(c);
        const std::size_t m = size_of(c);
        dof.resize(m);
        for (std::size_t a = 0; a < nodes.size(); ++a)
          for (int i = 0; i < components; ++i) dof[a * components + i] = nodes[a] * components + i;
        const double* ke = k_batch.data() + offset[k - begin];
        const double* f = f_batch.data() + f_offset[k - begin];
        for (std::size_t b = 0; b < m; ++b) {
          const Index col = dof[b];
          if (col < lo || col >= hi) continue;
          system.rhs[col] += f[b];
          const int* first = inner + outer[col];
          const int* last = inner + outer[col + 1];
          for (std::size_t a = 0; a < m; ++a)
            if (dof[a] >= col)
              values[std::lower_bound(first, last, dof[a]) - inner] += ke[b * m + a];
        }
      }
    });
    begin = end;
  }
  return system;
}

}  // namespace volmesh::fem::detail
