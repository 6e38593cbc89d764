#include "volmesh/partition/dual_graph.hpp"

#include <algorithm>

#include "volmesh/core/errors.hpp"

namespace volmesh {

DualGraph build_dual_graph(const PolyMesh& mesh, const std::string& source) {
  const Index cells = mesh.num_cells();
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.is_boundary(f)) continue;
    const Index o = mesh.owner[f], n = mesh.neighbour[f];
    if (o < 0 || o >= cells || n < 0 || n >= cells)
      throw InputError(source + ": face " + std::to_string(f) + ": cell index out of range (" +
                       std::to_string(cells) + " cells)");
    if (o == n)
      throw InputError(source + ": face " + std::to_string(f) + ": cell " + std::to_string(o) +
                       " on both sides");
  }
  // Two CSR entries per internal face, before merging faces shared by the same two cells.
  std::int64_t entries = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) entries += mesh.is_boundary(f) ? 0 : 2;
  if (entries > kMaxIndex)
    throw InputError(source + ": " + std::to_string(entries / 2) +
                     " internal faces: too many for 32-bit METIS indices");

  const CellFaces cell_faces = build_cell_faces(mesh);
  DualGraph graph;
  graph.xadj.reserve(static_cast<std::size_t>(cells) + 1);
  graph.adjncy.reserve(static_cast<std::size_t>(entries));
  graph.adjwgt.reserve(static_cast<std::size_t>(entries));
  std::vector<Index> others;
  for (Index c = 0; c < cells; ++c) {
    others.clear();
    for (Index f : cell_faces.of(c))
      if (!mesh.is_boundary(f))
        others.push_back(mesh.owner[f] == c ? mesh.neighbour[f] : mesh.owner[f]);
    std::sort(others.begin(), others.end());
    for (std::size_t i = 0; i < others.size();) {
      std::size_t j = i + 1;
      while (j < others.size() && others[j] == others[i]) ++j;
      graph.adjncy.push_back(others[i]);
      graph.adjwgt.push_back(static_cast<Index>(j - i));
      i = j;
    }
    graph.xadj.push_back(static_cast<Index>(graph.adjncy.size()));
  }
  return graph;
}

std::vector<Index> part_components(const DualGraph& graph, std::span<const Index> cell_part,
                                   Index parts) {
  std::vector<Index> components(parts, 0);
  std::vector<char> seen(graph.num_vertices(), 0);
  std::vector<Index> stack;
  for (Index start = 0; start < graph.num_vertices(); ++start) {
    if (seen[start]) continue;
    const Index part = cell_part[start];
    ++components[part];
    seen[start] = 1;
    stack.assign(1, start);
    while (!stack.empty()) {
      const Index c = stack.back();
      stack.pop_back();
      for (Index other : graph.neighbours(c))
        if (!seen[other] && cell_part[other] == part) {
          seen[other] = 1;
          stack.push_back(other);
        }
    }
  }
  return components;
}

}  // namespace volmesh
