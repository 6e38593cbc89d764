#include "volmesh/core/topology.hpp"

#include <algorithm>
#include <cstdint>

namespace volmesh {

MeshEdges build_edges(const PolyMesh& mesh) {
  MeshEdges e;
  e.face_edge_offsets = mesh.face_offsets;
  const std::size_t n = mesh.face_vertices.size();
  // One key per face corner, sorted once: each run of equal keys is one edge.
  std::vector<std::pair<std::uint64_t, Index>> keyed(n);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto loop = mesh.face(f);
    const std::size_t m = loop.size();
    for (std::size_t k = 0; k < m; ++k) {
      Index a = loop[k], b = loop[(k + 1) % m];
      if (a > b) std::swap(a, b);
      keyed[mesh.face_offsets[f] + k] = {std::uint64_t(std::uint32_t(a)) << 32 | std::uint32_t(b),
                                         static_cast<Index>(mesh.face_offsets[f] + k)};
    }
  }
  std::sort(keyed.begin(), keyed.end());
  e.face_edges.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 0 || keyed[i].first != keyed[i - 1].first)
      e.edges.push_back({static_cast<Index>(keyed[i].first >> 32),
                         static_cast<Index>(keyed[i].first & 0xffffffffu)});
    e.face_edges[keyed[i].second] = static_cast<Index>(e.edges.size()) - 1;
  }
  return e;
}

PointCells build_point_cells(const PolyMesh& mesh) {
  std::vector<std::pair<Index, Index>> pairs;  // (point, cell)
  pairs.reserve(2 * mesh.face_vertices.size());
  for (Index f = 0; f < mesh.num_faces(); ++f)
    for (Index v : mesh.face(f)) {
      pairs.emplace_back(v, mesh.owner[f]);
      if (!mesh.is_boundary(f)) pairs.emplace_back(v, mesh.neighbour[f]);
    }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  PointCells pc;
  pc.offsets.assign(mesh.num_points() + 1, 0);
  for (const auto& [p, c] : pairs) ++pc.offsets[p + 1];
  for (Index p = 0; p < mesh.num_points(); ++p) pc.offsets[p + 1] += pc.offsets[p];
  pc.cells.reserve(pairs.size());
  for (const auto& pair : pairs) pc.cells.push_back(pair.second);
  return pc;
}

}  // namespace volmesh
