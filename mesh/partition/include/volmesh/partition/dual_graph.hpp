#pragma once
// The face-adjacency (dual) graph of a PolyMesh: one vertex per cell, one edge per pair of
// cells that share an internal face. It is built from the faces themselves, so an octree cell
// next to four smaller ones has four edges on that side and any polyhedron works;
// METIS_PartMeshDual, which guesses adjacency from shared corner nodes of element
// connectivities, gets both wrong.
#include <span>
#include <string>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// CSR arrays as METIS takes them (METIS's idx_t is Index, checked where METIS is called):
// the neighbours of cell c are adjncy[xadj[c] .. xadj[c+1]), sorted, and adjwgt holds the
// number of internal faces c shares with each of them. With these weights METIS's edge cut
// is the number of faces between parts.
struct DualGraph {
  std::vector<Index> xadj{0};
  std::vector<Index> adjncy;
  std::vector<Index> adjwgt;

  Index num_vertices() const { return static_cast<Index>(xadj.size()) - 1; }
  Index num_edges() const { return static_cast<Index>(adjncy.size() / 2); }
  Index degree(Index c) const { return xadj[c + 1] - xadj[c]; }
  std::span<const Index> neighbours(Index c) const {
    return {adjncy.data() + xadj[c], static_cast<std::size_t>(degree(c))};
  }
  std::span<const Index> weights(Index c) const {
    return {adjwgt.data() + xadj[c], static_cast<std::size_t>(degree(c))};
  }
};

// Throws InputError, naming `source` and the face, when an internal face has a cell index out
// of range or the same cell on both sides, or when the graph does not fit 32-bit indices.
DualGraph build_dual_graph(const PolyMesh& mesh, const std::string& source = "mesh");

// Number of connected pieces of each part: the components of the subgraph made of the edges
// whose two cells lie in the same part. 1 means the part is contiguous, 0 that it is empty.
// With one part (cell_part all 0) this counts the pieces of the whole mesh.
std::vector<Index> part_components(const DualGraph& graph, std::span<const Index> cell_part,
                                   Index parts);

}  // namespace volmesh
