#include "volmesh/hexdc/project.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "feature_point.hpp"
#include "hex_mesh_geometry.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/hexdc/hex_quality.hpp"
#include "volmesh/quality/hex_metrics.hpp"

namespace volmesh {

ProjectStats project_boundary(HexMesh& mesh, const SurfaceProjector& closest_point,
                              const ProjectOptions& options) {
  using namespace hexdc_detail;
  if (options.halvings < 0 || options.passes < 1)
    throw InputError("project_boundary: halvings must not be negative, passes at least 1");
  const double cos_feature = feature_cosine("project_boundary", options.feature_angle_deg);
  if (!(options.tolerance >= 0.0))
    throw InputError("project_boundary: tolerance must not be negative");
  ProjectStats stats;
  if (mesh.cells.empty()) return stats;

  const std::vector<std::vector<Index>> hexes = hexes_of_nodes(mesh);
  const std::vector<std::vector<Index>> quads = boundary_quads_of_nodes(mesh);
  Vec3 lo = mesh.points.front(), hi = lo;
  for (const Vec3& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double on_surface = options.tolerance * (hi - lo).norm();

  std::vector<char> pinned(mesh.points.size(), 0);
  const std::vector<PinnedNode> no_pins;
  const std::vector<PinnedNode>& pins = options.pinned != nullptr ? *options.pinned : no_pins;
  for (const PinnedNode& pin : pins) pinned[static_cast<std::size_t>(pin.node)] = 1;
  // The nodes to project and the feature nodes, in index order.
  std::vector<std::size_t> movable, features;
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (quads[v].empty() || hexes[v].empty()) continue;
    ++stats.boundary_nodes;
    if (pinned[v]) {
      ++stats.pinned_nodes;
      continue;
    }
    if (on_feature(mesh, quads[v], cos_feature)) {
      features.push_back(v);
      continue;
    }
    const double distance = (closest_point(mesh.points[v]) - mesh.points[v]).norm();
    stats.max_distance_before = std::max(stats.max_distance_before, distance);
    movable.push_back(v);
  }
  stats.feature_nodes = static_cast<Index>(features.size());

  HexState state = hex_state(mesh, hex_scaled_jacobian);
  stats.min_scaled_jacobian_before = least_quality(state);
  stats.invalid_hexes_before = invalid_count(state);
  std::vector<std::size_t> first_judged(mesh.points.size(), 0);  // guarded_move's `first`
  std::vector<HexGrade> trial;
  const auto move = [&](std::size_t v, const Vec3& target, double floor) {
    Vec3 step = target - mesh.points[v];
    if (step.norm() <= on_surface) return;
    for (int k = 0; k <= options.halvings; ++k, step *= 0.5)
      if (guarded_move(mesh, hexes[v], v, mesh.points[v] + step, floor, state, first_judged[v],
                       trial))
        return;
  };
  for (int pass = 0; pass < options.passes; ++pass) {
    // Pinned nodes and features first, so that the nodes beside them are projected next to
    // where they end.
    for (const PinnedNode& pin : pins) move(static_cast<std::size_t>(pin.node), pin.target, options.pinned_min_scaled_jacobian);
    for (const std::size_t v : features)
      move(v, feature_point(mesh, quads[v], closest_point, v, shortest_edge(mesh, hexes[v], v)),
           options.min_scaled_jacobian);
    for (const std::size_t v : movable)
      move(v, closest_point(mesh.points[v]), options.min_scaled_jacobian);
  }

  for (const std::size_t v : movable) {
    const double distance = (closest_point(mesh.points[v]) - mesh.points[v]).norm();
    if (distance <= on_surface) continue;
    ++stats.held_back;
    stats.max_distance_left = std::max(stats.max_distance_left, distance);
  }
  for (const PinnedNode& pin : pins)
    if ((mesh.points[static_cast<std::size_t>(pin.node)] - pin.target).norm() > on_surface) ++stats.pinned_held_back;
  for (const std::size_t v : features)
    stats.max_feature_distance = std::max(
        stats.max_feature_distance, (closest_point(mesh.points[v]) - mesh.points[v]).norm());
  stats.projected = stats.boundary_nodes - stats.pinned_nodes - stats.feature_nodes - stats.held_back;
  stats.min_scaled_jacobian_after = least_quality(state);
  stats.invalid_hexes_after = invalid_count(state);
  return stats;
}

}  // namespace volmesh
