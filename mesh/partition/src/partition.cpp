#include "volmesh/core/stopwatch.hpp"
#include "volmesh/partition/partition.hpp"

#include <metis.h>

#include <algorithm>
#include <numeric>
#include <type_traits>

#include "volmesh/core/errors.hpp"

namespace volmesh {

// The graph's CSR arrays go to METIS as they are.
static_assert(std::is_same_v<idx_t, Index>, "METIS must be built with 32-bit idx_t");

namespace {

// Any fixed value: the same graph and options then give the same parts on every run.
constexpr idx_t kSeed = 20240531;
// K-way's load-imbalance target in thousandths above 1 (partition.hpp).
constexpr idx_t kKWayUFactor = 10;

void check_options(const DualGraph& graph, const PartitionOptions& options,
                   const std::string& source) {
  const Index cells = graph.num_vertices();
  if (options.parts < 1)
    throw InputError(source + ": cannot make " + std::to_string(options.parts) +
                     " parts (at least 1)");
  if (options.parts > cells)
    throw InputError(source + ": cannot split " + std::to_string(cells) + " cells into " +
                     std::to_string(options.parts) + " non-empty parts");
  const auto& w = options.cell_weights;
  if (w.empty()) return;
  if (w.size() != static_cast<std::size_t>(cells))
    throw InputError(source + ": " + std::to_string(w.size()) + " cell weights for " +
                     std::to_string(cells) + " cells");
  const auto negative = std::find_if(w.begin(), w.end(), [](Index x) { return x < 0; });
  if (negative != w.end())
    throw InputError(source + ": cell " + std::to_string(negative - w.begin()) + ": weight " +
                     std::to_string(*negative) + " (weights are >= 0)");
  const std::int64_t total = std::accumulate(w.begin(), w.end(), std::int64_t{0});
  if (total == 0) throw InputError(source + ": every cell weight is 0");
  if (total > kMaxIndex)
    throw InputError(source + ": total cell weight " + std::to_string(total) +
                     " exceeds the 32-bit METIS limit");
}

std::vector<Index> run_metis(const DualGraph& graph, const PartitionOptions& options,
                             bool recursive, bool contiguous, const std::string& source) {
  idx_t vertices = graph.num_vertices(), constraints = 1, parts = options.parts, cut = 0;
  idx_t metis_options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(metis_options);
  metis_options[METIS_OPTION_SEED] = kSeed;
  metis_options[METIS_OPTION_NUMBERING] = 0;
  metis_options[METIS_OPTION_CONTIG] = contiguous ? 1 : 0;
  if (!recursive) metis_options[METIS_OPTION_UFACTOR] = kKWayUFactor;
  // METIS takes non-const pointers but does not write through them.
  auto* xadj = const_cast<idx_t*>(graph.xadj.data());
  auto* adjncy = const_cast<idx_t*>(graph.adjncy.data());
  auto* adjwgt = const_cast<idx_t*>(graph.adjwgt.data());
  auto* vwgt =
      options.cell_weights.empty() ? nullptr : const_cast<idx_t*>(options.cell_weights.data());
  std::vector<Index> part(graph.num_vertices(), 0);
  const int status =
      recursive
          ? METIS_PartGraphRecursive(&vertices, &constraints, xadj, adjncy, vwgt, nullptr, adjwgt,
                                     &parts, nullptr, nullptr, metis_options, &cut, part.data())
          : METIS_PartGraphKway(&vertices, &constraints, xadj, adjncy, vwgt, nullptr, adjwgt,
                                &parts, nullptr, nullptr, metis_options, &cut, part.data());
  if (status == METIS_ERROR_MEMORY)
    throw InputError(source + ": METIS ran out of memory making " + std::to_string(options.parts) +
                     " parts");
  if (status != METIS_OK)
    throw InputError(source + ": METIS failed to make " + std::to_string(options.parts) +
                     " parts (status " + std::to_string(status) + ")");
  return part;
}

// METIS can leave parts empty when K nears the number of cells. Each empty part takes one cell
// of the part with the most cells: the cell with the fewest neighbours in that part, so that
// a leaf is taken when there is one and the donor stays connected. Returns the parts filled.
Index fill_empty_parts(const DualGraph& graph, std::vector<Index>& cell_part, Index parts) {
  std::vector<Index> size(parts, 0);
  for (Index p : cell_part) ++size[p];
  Index filled = 0;
  for (Index p = 0; p < parts; ++p) {
    if (size[p] > 0) continue;
    const auto largest = std::max_element(size.begin(), size.end());
    const auto donor = static_cast<Index>(largest - size.begin());
    Index taken = kNoIndex, fewest = 0;
    for (Index c = 0; c < graph.num_vertices(); ++c) {
      if (cell_part[c] != donor) continue;
      const auto others = graph.neighbours(c);
      const auto inside = static_cast<Index>(std::count_if(
          others.begin(), others.end(), [&](Index o) { return cell_part[o] == donor; }));
      if (taken == kNoIndex || inside < fewest) taken = c, fewest = inside;
    }
    cell_part[taken] = p;
    --size[donor];
    ++size[p];
    ++filled;
  }
  return filled;
}

}  // namespace

bool PartitionStats::all_contiguous() const {
  return std::all_of(part_components.begin(), part_components.end(),
                     [](Index n) { return n == 1; });
}

PartitionStats partition_statistics(const DualGraph& graph, std::span<const Index> cell_part,
                                    Index parts, std::span<const Index> cell_weights) {
  PartitionStats stats;
  stats.parts = parts;
  stats.part_cells.assign(parts, 0);
  stats.part_weights.assign(parts, 0);
  stats.part_interface_faces.assign(parts, 0);
  stats.part_neighbours.assign(parts, 0);
  std::vector<std::vector<Index>> touching(parts);
  for (Index c = 0; c < graph.num_vertices(); ++c) {
    const Index p = cell_part[c];
    ++stats.part_cells[p];
    stats.part_weights[p] += cell_weights.empty() ? 1 : cell_weights[c];
    const auto others = graph.neighbours(c);
    const auto faces = graph.weights(c);
    for (std::size_t k = 0; k < others.size(); ++k) {
      const Index q = cell_part[others[k]];
      if (q == p) continue;
      stats.part_interface_faces[p] += faces[k];
      if (others[k] > c) stats.edge_cut += faces[k];
      touching[p].push_back(q);
    }
  }
  for (Index p = 0; p < parts; ++p) {
    auto& t = touching[p];
    std::sort(t.begin(), t.end());
    stats.part_neighbours[p] = static_cast<Index>(std::unique(t.begin(), t.end()) - t.begin());
  }
  const std::int64_t total =
      std::accumulate(stats.part_weights.begin(), stats.part_weights.end(), std::int64_t{0});
  const std::int64_t largest =
      *std::max_element(stats.part_weights.begin(), stats.part_weights.end());
  stats.imbalance =
      total > 0 ? static_cast<double>(largest) * parts / static_cast<double>(total) : 1.0;
  stats.part_components = part_components(graph, cell_part, parts);
  return stats;
}

Partition partition_graph(const DualGraph& graph, const PartitionOptions& options,
                          const std::string& source) {
  check_options(graph, options, source);
  const std::vector<Index> whole(graph.num_vertices(), 0);
  const Index mesh_components = part_components(graph, whole, 1).front();
  const bool contiguous = options.contiguous && mesh_components == 1 && options.parts > 1;
  const bool recursive = !contiguous && options.method == PartitionMethod::Recursive;

  Partition result;
  const Clock::time_point start = Clock::now();
  result.cell_part =
      options.parts == 1 ? whole : run_metis(graph, options, recursive, contiguous, source);
  const double metis_seconds = seconds_since(start);
  const Index filled = fill_empty_parts(graph, result.cell_part, options.parts);

  result.stats = partition_statistics(graph, result.cell_part, options.parts, options.cell_weights);
  result.stats.method = options.parts == 1 ? "none" : recursive ? "recursive" : "kway";
  result.stats.mesh_components = mesh_components;
  result.stats.contiguity_enforced = contiguous;
  result.stats.metis_seconds = metis_seconds;
  result.stats.filled_empty_parts = filled;
  return result;
}

Partition partition_mesh(const PolyMesh& mesh, const PartitionOptions& options,
                         const std::string& source) {
  const Clock::time_point start = Clock::now();
  const DualGraph graph = build_dual_graph(mesh, source);
  const double graph_seconds = seconds_since(start);
  Partition result = partition_graph(graph, options, source);
  result.stats.graph_seconds = graph_seconds;
  return result;
}

}  // namespace volmesh
