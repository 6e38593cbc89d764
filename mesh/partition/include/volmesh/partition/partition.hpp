#pragma once
// Cell partitioning with METIS on the face-adjacency graph, and the statistics a user judges
// a partition by: edge cut, imbalance, interface faces, contiguity.
#include <span>
#include <string>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/partition/dual_graph.hpp"

namespace volmesh {

// K-way is the default: on 10^6 hexes it takes 0.6 - 1.0 s of CPU for K = 2 .. 64 where
// recursive bisection takes 0.5 - 2.5 s, their edge cuts are within 5% of each other either
// way, and only k-way can make the parts contiguous (validation/partition/run.sh). It runs
// with a 1% imbalance target (METIS_OPTION_UFACTOR 10): METIS's default of 3% leaves k-way
// partitions of tet meshes at 1.029, at the edge of what users accept.
enum class PartitionMethod { KWay, Recursive };

struct PartitionOptions {
  Index parts = 1;
  PartitionMethod method = PartitionMethod::KWay;
  // Ask METIS for connected parts (METIS_OPTION_CONTIG, k-way only). A mesh in several pieces
  // cannot have them: it is then partitioned without the constraint and the statistics say so.
  bool contiguous = false;
  // One weight >= 0 per cell (e.g. its face count, for a solver whose cost grows with it);
  // empty: every cell weighs 1. Parts are balanced by weight.
  std::vector<Index> cell_weights = {};
};

struct PartitionStats {
  Index parts = 0;
  std::string method;      // "none" (one part, METIS not called), "kway" or "recursive"
  Index edge_cut = 0;      // internal faces whose two cells lie in different parts
  double imbalance = 1.0;  // largest part weight / mean part weight (weight = cells unweighted)
  std::vector<Index> part_cells;
  std::vector<std::int64_t> part_weights;
  std::vector<Index> part_interface_faces;  // faces of the part shared with another part
  std::vector<Index> part_neighbours;       // other parts it shares a face with
  std::vector<Index> part_components;       // connected pieces of each part (1: contiguous)
  Index mesh_components = 0;                // connected pieces of the whole mesh
  bool contiguity_enforced = false;         // METIS_OPTION_CONTIG was used
  Index filled_empty_parts = 0;             // parts METIS left empty (partition_graph)
  double graph_seconds = 0.0, metis_seconds = 0.0;

  bool all_contiguous() const;
};

struct Partition {
  std::vector<Index> cell_part;  // part of each cell, 0 .. parts-1
  PartitionStats stats;
};

// Every part gets at least one cell: METIS can leave parts empty when K nears the number of
// cells, and each of those then takes one cell of the largest part (partition.cpp).
// Throws InputError (naming `source`) for parts < 1, more parts than cells, weights of the
// wrong size or negative, and when METIS fails. Deterministic: METIS runs with a fixed seed,
// and one part never calls METIS (METIS 5.1 crashes there).
Partition partition_mesh(const PolyMesh& mesh, const PartitionOptions& options,
                         const std::string& source = "mesh");
// The same on a graph built once, for callers that try several part counts.
Partition partition_graph(const DualGraph& graph, const PartitionOptions& options,
                          const std::string& source = "mesh");

// Statistics of any assignment of cells to parts (timings and method left empty).
PartitionStats partition_statistics(const DualGraph& graph, std::span<const Index> cell_part,
                                    Index parts, std::span<const Index> cell_weights = {});

}  // namespace volmesh
