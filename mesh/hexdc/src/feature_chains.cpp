// Boundary chains along the input's creases (feature_layer.hpp).
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <utility>

#include "polyline.hpp"
#include "volmesh/hexdc/feature_layer.hpp"

namespace volmesh {
namespace {

using hexdc_detail::distance_to_polyline;

// A chain edge through a node another chain took costs this many times its length more: chains
// cross only where nothing else is left.
constexpr double kTaken = 10.0;

struct BoundaryGraph {
  std::vector<Index> nodes;                      // boundary nodes, in index order
  std::vector<std::vector<Index>> neighbours;    // per mesh node, in index order
};

BoundaryGraph boundary_graph(const HexMesh& mesh) {
  BoundaryGraph g;
  g.neighbours.resize(mesh.points.size());
  for (const auto& quad : mesh.boundary_faces)
    for (std::size_t c = 0; c < 4; ++c) {
      g.neighbours[static_cast<std::size_t>(quad[c])].push_back(quad[(c + 1) % 4]);
      g.neighbours[static_cast<std::size_t>(quad[(c + 1) % 4])].push_back(quad[c]);
    }
  for (std::size_t v = 0; v < g.neighbours.size(); ++v) {
    auto& n = g.neighbours[v];
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
    if (!n.empty()) g.nodes.push_back(static_cast<Index>(v));
  }
  return g;
}

Index nearest_node(const HexMesh& mesh, const BoundaryGraph& g, const Vec3& p) {
  Index best = g.nodes.front();
  double least = std::numeric_limits<double>::infinity();
  for (const Index v : g.nodes) {
    const double d = (mesh.points[static_cast<std::size_t>(v)] - p).squaredNorm();
    if (d < least) {
      least = d;
      best = v;
    }
  }
  return best;
}

// The cheapest path from s to t along boundary edges (Dijkstra), empty if there is none.
std::vector<Index> cheapest_path(const HexMesh& mesh, const BoundaryGraph& g, Index s, Index t,
                                 const std::vector<Vec3>& crease, const std::vector<char>& taken) {
  const std::size_t n = mesh.points.size();
  std::vector<double> cost(n, std::numeric_limits<double>::infinity());
  std::vector<Index> from(n, -1);
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  cost[static_cast<std::size_t>(s)] = 0.0;
  open.emplace(0.0, s);
  while (!open.empty()) {
    const auto [c, u] = open.top();
    open.pop();
    if (u == t) break;
    if (c > cost[static_cast<std::size_t>(u)]) continue;
    const Vec3& pu = mesh.points[static_cast<std::size_t>(u)];
    for (const Index w : g.neighbours[static_cast<std::size_t>(u)]) {
      const Vec3& pw = mesh.points[static_cast<std::size_t>(w)];
      const double length = (pw - pu).norm();
      double step = length + kOffCrease * distance_to_polyline(0.5 * (pu + pw), crease);
      if (taken[static_cast<std::size_t>(w)] && w != t) step += kTaken * length;
      if (c + step < cost[static_cast<std::size_t>(w)]) {
        cost[static_cast<std::size_t>(w)] = c + step;
        from[static_cast<std::size_t>(w)] = u;
        open.emplace(c + step, w);
      }
    }
  }
  if (from[static_cast<std::size_t>(t)] < 0) return {};
  std::vector<Index> path{t};
  while (path.back() != s) path.push_back(from[static_cast<std::size_t>(path.back())]);
  std::reverse(path.begin(), path.end());
  return path;
}

// Where each node of `path` belongs on `line`, which it follows from end to end: at the same
// share of the line's length as the node's of the path's, so that the nodes keep their order
// and spacing along the crease (their closest points could coincide, beside an end).
std::vector<Vec3> spread_along(const HexMesh& mesh, const std::vector<Index>& path,
                               const std::vector<Vec3>& line) {
  const auto at = [&](std::size_t i) { return mesh.points[static_cast<std::size_t>(path[i])]; };
  std::vector<double> share(path.size(), 0.0);
  for (std::size_t i = 1; i < path.size(); ++i) share[i] = share[i - 1] + (at(i) - at(i - 1)).norm();
  std::vector<double> arc(line.size(), 0.0);
  for (std::size_t i = 1; i < line.size(); ++i) arc[i] = arc[i - 1] + (line[i] - line[i - 1]).norm();
  std::vector<Vec3> targets;
  std::size_t segment = 1;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const double s = share.back() > 0.0 ? share[i] / share.back() * arc.back() : 0.0;
    while (segment + 1 < line.size() && arc[segment] < s) ++segment;
    const double length = arc[segment] - arc[segment - 1];
    const double t = length > 0.0 ? std::clamp((s - arc[segment - 1]) / length, 0.0, 1.0) : 0.0;
    targets.push_back(line[segment - 1] + t * (line[segment] - line[segment - 1]));
  }
  return targets;
}

}  // namespace

FeatureLayer chain_features(const HexMesh& mesh, const SurfaceFeatures& features) {
  FeatureLayer layer;
  const BoundaryGraph g = boundary_graph(mesh);
  if (g.nodes.empty()) return layer;
  std::map<Index, PinnedNode> pinned;
  std::vector<char> taken(mesh.points.size(), 0);
  for (const Vec3& corner : features.corners) {
    const Index v = nearest_node(mesh, g, corner);
    if (pinned.emplace(v, PinnedNode{v, corner, true}).second) taken[static_cast<std::size_t>(v)] = 1;
  }
  for (std::size_t c = 0; c < features.creases.size(); ++c) {
    const std::vector<Vec3>& crease = features.creases[c];
    // A closed crease in two halves, so that its chain has two distinct ends.
    std::vector<std::vector<Vec3>> parts{crease};
    if (crease.size() > 2 && crease.front() == crease.back()) {
      const auto middle = crease.begin() + static_cast<std::ptrdiff_t>(crease.size() / 2);
      parts = {std::vector<Vec3>(crease.begin(), middle + 1), std::vector<Vec3>(middle, crease.end())};
    }
    for (const auto& part : parts) {
      const Index s = nearest_node(mesh, g, part.front()), t = nearest_node(mesh, g, part.back());
      if (s == t) continue;
      std::vector<Index> path = cheapest_path(mesh, g, s, t, crease, taken);
      if (path.empty()) continue;
      const std::vector<Vec3> targets = spread_along(mesh, path, part);
      for (std::size_t i = 0; i < path.size(); ++i) {
        taken[static_cast<std::size_t>(path[i])] = 1;
        pinned.emplace(path[i], PinnedNode{path[i], targets[i], false});
      }
      layer.chains.push_back({static_cast<Index>(c), std::move(path)});
    }
  }
  for (const auto& [v, pin] : pinned) layer.pinned.push_back(pin);
  return layer;
}

}  // namespace volmesh
