#include "volmesh/hexdc/hex_mesh_stats.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "hex_mesh_geometry.hpp"
#include "volmesh/hexdc/hex_quality.hpp"

namespace volmesh {

HexMeshStats hex_mesh_stats(const HexMesh& mesh) {
  HexMeshStats s;
  if (mesh.cells.empty()) return s;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  s.cells = mesh.num_cells();
  s.min_edge = kInf;
  s.min_scaled_jacobian = kInf;
  double jacobian_sum = 0.0;
  std::vector<Index> hexes_at(mesh.points.size(), 0);
  for (Index c = 0; c < s.cells; ++c) {
    for (const Index p : mesh.cells[c]) ++hexes_at[p];
    const std::array<Vec3, 8> corners = hexdc_detail::hex_corners(mesh, c);
    const HexQuality q = hex_quality(corners);
    s.max_edge = std::max(s.max_edge, q.max_edge);
    s.min_edge = std::min(s.min_edge, q.min_edge);
    s.max_aspect_ratio =
        std::max(s.max_aspect_ratio, q.min_edge > 0.0 ? q.max_edge / q.min_edge : kInf);
    s.max_quad_distortion_deg = std::max(s.max_quad_distortion_deg, q.max_quad_distortion_deg);
    s.min_scaled_jacobian = std::min(s.min_scaled_jacobian, q.scaled_jacobian);
    jacobian_sum += q.scaled_jacobian;
    if (q.corner_tets_positive) continue;
    if (s.degenerate++ == 0) {
      s.first_degenerate = c;
      for (const Vec3& p : corners) s.first_degenerate_centre += p / 8.0;
    }
  }
  s.mean_scaled_jacobian = jacobian_sum / static_cast<double>(s.cells);
  for (const Index n : hexes_at)
    if (n > 0) {
      ++s.nodes;
      ++s.valence[n];
    }
  return s;
}

}  // namespace volmesh
