// The closure of refinement marks and the marking helpers of refine.hpp.
#include <algorithm>

#include "refine_templates.hpp"
#include "volmesh/hexdc/refine.hpp"

namespace volmesh {

namespace {

constexpr int kUnreached = -1;

}  // namespace

Index close_refinement_marks(const HexMesh& mesh, std::vector<char>& marked_nodes) {
  Index passes = 0;
  for (bool changed = true; changed;) {
    changed = false;
    ++passes;
    for (const auto& cell : mesh.cells) {
      const unsigned mask = hexdc_detail::corner_mask(cell, marked_nodes);
      const unsigned closed = hexdc_detail::closed_mask(mask);
      if (closed == mask) continue;
      for (std::size_t c = 0; c < 8; ++c)
        if ((closed >> c) & 1u) marked_nodes[static_cast<std::size_t>(cell[c])] = 1;
      changed = true;
    }
  }
  return passes;
}

std::vector<char> mark_boundary_layers(const HexMesh& mesh, int layers) {
  std::vector<char> marked(mesh.points.size(), 0);
  if (layers <= 0) return marked;
  // Hex layers from the boundary: 0 on boundary quads, k for the other nodes of a hex that has
  // a node at k - 1.
  std::vector<int> layer(mesh.points.size(), kUnreached);
  for (const auto& quad : mesh.boundary_faces)
    for (const Index v : quad) layer[static_cast<std::size_t>(v)] = 0;
  for (int k = 1; k <= layers; ++k)
    for (const auto& cell : mesh.cells) {
      const bool touches = std::any_of(cell.begin(), cell.end(), [&](Index v) {
        return layer[static_cast<std::size_t>(v)] == k - 1;
      });
      if (!touches) continue;
      for (const Index v : cell)
        if (layer[static_cast<std::size_t>(v)] == kUnreached) layer[static_cast<std::size_t>(v)] = k;
    }
  for (std::size_t v = 0; v < layer.size(); ++v) marked[v] = layer[v] != kUnreached ? 1 : 0;
  return marked;
}

std::vector<char> mark_box(const HexMesh& mesh, const Eigen::AlignedBox3d& box) {
  std::vector<char> marked(mesh.points.size(), 0);
  for (std::size_t v = 0; v < mesh.points.size(); ++v) marked[v] = box.contains(mesh.points[v]) ? 1 : 0;
  return marked;
}

}  // namespace volmesh
