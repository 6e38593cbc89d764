#include "volmesh/hexdc/smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "hex_mesh_geometry.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/hexdc/hex_quality.hpp"
#include "volmesh/quality/hex_metrics.hpp"

namespace volmesh {
namespace {

using namespace hexdc_detail;

// A step shorter than this fraction of an edge at the node counts as no move:
// a converged node would otherwise be "moved" by round-off in every sweep.
constexpr double kNegligibleStep = 1e-12;
// No hex may get worse than the node's worst: guarded_move's floor is never the bound.
constexpr double kNoFloor = std::numeric_limits<double>::infinity();

struct NodeLinks {
  std::vector<std::vector<Index>> hexes;       // hexes having the node as a corner
  std::vector<std::vector<Index>> neighbours;  // edge neighbours through any hex edge
  std::vector<std::vector<Index>> boundary_neighbours;  // through boundary-quad edges
  std::vector<std::vector<Index>> quads;                // boundary quads having the node
};

void add_unique(std::vector<Index>& list, Index value) {
  if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}

NodeLinks link_nodes(const HexMesh& mesh) {
  const auto n = static_cast<std::size_t>(mesh.num_points());
  NodeLinks links{std::vector<std::vector<Index>>(n), std::vector<std::vector<Index>>(n),
                  std::vector<std::vector<Index>>(n), std::vector<std::vector<Index>>(n)};
  for (Index h = 0; h < mesh.num_cells(); ++h) {
    const auto& cell = mesh.cells[static_cast<std::size_t>(h)];
    for (const Index v : cell) add_unique(links.hexes[static_cast<std::size_t>(v)], h);
    for (const auto& [a, b] : kHexEdges) {
      add_unique(links.neighbours[static_cast<std::size_t>(cell[a])], cell[b]);
      add_unique(links.neighbours[static_cast<std::size_t>(cell[b])], cell[a]);
    }
  }
  for (std::size_t q = 0; q < mesh.boundary_faces.size(); ++q) {
    const auto& quad = mesh.boundary_faces[q];
    for (std::size_t c = 0; c < 4; ++c) {
      const Index v = quad[c], next = quad[(c + 1) % 4];
      links.quads[static_cast<std::size_t>(v)].push_back(static_cast<Index>(q));
      add_unique(links.boundary_neighbours[static_cast<std::size_t>(v)], next);
      add_unique(links.boundary_neighbours[static_cast<std::size_t>(next)], v);
    }
  }
  return links;
}

Vec3 mean_of(const HexMesh& mesh, const std::vector<Index>& nodes) {
  Vec3 sum = Vec3::Zero();
  for (const Index v : nodes) sum += mesh.points[static_cast<std::size_t>(v)];
  return sum / static_cast<double>(nodes.size());
}

// The full Laplacian step of node v; on the boundary, projected onto the tangent plane.
Vec3 laplacian_step(const HexMesh& mesh, const NodeLinks& links, std::size_t v) {
  const Vec3& x = mesh.points[v];
  if (links.quads[v].empty()) return mean_of(mesh, links.neighbours[v]) - x;
  const Vec3 step = mean_of(mesh, links.boundary_neighbours[v]) - x;
  const Vec3 normal = node_normal(mesh, links.quads[v]);
  return step - step.dot(normal) * normal;
}

}  // namespace

SmoothingStats smooth_hexes(HexMesh& mesh, const SmoothingOptions& options) {
  if (options.sweeps < 0 || options.halvings < 0)
    throw InputError("smooth_hexes: sweeps and halvings must not be negative");
  const double cos_feature = feature_cosine("smooth_hexes", options.feature_angle_deg);
  SmoothingStats stats;
  if (mesh.cells.empty()) return stats;
  const NodeLinks links = link_nodes(mesh);
  std::vector<bool> movable(mesh.points.size());
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    movable[v] = !links.hexes[v].empty() &&
                 (links.quads[v].empty() || !on_feature(mesh, links.quads[v], cos_feature));

  HexState state = hex_state(mesh, hex_scaled_jacobian);
  stats.min_scaled_jacobian_before = least_quality(state);
  stats.invalid_hexes_before = invalid_count(state);
  // A node's move depends only on the nodes sharing a hex or a boundary quad with it: one that
  // found no move stays unvisited until one of those moves (its `changed` mark), since it would
  // find none again. Its last outcome is counted again for it, as if it had been visited.
  std::vector<char> changed(mesh.points.size(), 1);
  std::vector<char> rejected(mesh.points.size(), 0);  // else its step was negligible
  std::vector<std::size_t> first_judged(mesh.points.size(), 0);  // guarded_move's `first`
  std::vector<HexGrade> trial;
  for (int sweep = 0; sweep < options.sweeps; ++sweep) {
    Index moved = 0;
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
      if (!movable[v]) continue;
      if (!changed[v]) {
        stats.moves_rejected += rejected[v];
        continue;
      }
      changed[v] = 0;
      Vec3 step = laplacian_step(mesh, links, v);
      const double edge =
          (mesh.points[v] - mesh.points[static_cast<std::size_t>(links.neighbours[v].front())])
              .norm();
      if (step.norm() <= kNegligibleStep * edge) {
        rejected[v] = 0;
        continue;
      }
      bool accepted = false;
      for (int k = 0; k <= options.halvings && !accepted; ++k, step *= 0.5)
        accepted = guarded_move(mesh, links.hexes[v], v, mesh.points[v] + step, kNoFloor, state,
                                first_judged[v], trial);
      rejected[v] = accepted ? 0 : 1;
      if (accepted) mark_around(mesh, links.hexes[v], links.quads[v], changed);
      ++(accepted ? stats.moves_accepted : stats.moves_rejected);
      moved += accepted ? 1 : 0;
    }
    ++stats.sweeps;
    stats.min_scaled_jacobian_per_sweep.push_back(least_quality(state));
    if (moved == 0) break;
  }
  stats.min_scaled_jacobian_after = least_quality(state);
  stats.invalid_hexes_after = invalid_count(state);
  return stats;
}

}  // namespace volmesh
