// The input surface's creases and corners (features.hpp).
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "hex_mesh_geometry.hpp"
#include "volmesh/hexdc/features.hpp"

namespace volmesh {
namespace {

using Edge = std::pair<Index, Index>;

Edge edge_key(Index a, Index b) { return {std::min(a, b), std::max(a, b)}; }

// Per vertex, its neighbours across sharp edges, in index order.
std::vector<std::vector<Index>> sharp_neighbours(const TriSurface& surface, double cos_feature) {
  std::vector<Vec3> normal(surface.triangles.size());
  std::map<Edge, std::vector<Index>> sides;
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const auto& tri = surface.triangles[t];
    const Vec3& a = surface.points[static_cast<std::size_t>(tri[0])];
    const Vec3& b = surface.points[static_cast<std::size_t>(tri[1])];
    const Vec3& c = surface.points[static_cast<std::size_t>(tri[2])];
    normal[t] = (b - a).cross(c - a).normalized();
    for (int k = 0; k < 3; ++k)
      sides[edge_key(tri[static_cast<std::size_t>(k)], tri[static_cast<std::size_t>((k + 1) % 3)])]
          .push_back(static_cast<Index>(t));
  }
  std::vector<std::vector<Index>> neighbours(surface.points.size());
  for (const auto& [edge, tris] : sides) {
    if (tris.size() != 2) continue;
    if (normal[static_cast<std::size_t>(tris[0])].dot(normal[static_cast<std::size_t>(tris[1])]) >=
        cos_feature)
      continue;
    neighbours[static_cast<std::size_t>(edge.first)].push_back(edge.second);
    neighbours[static_cast<std::size_t>(edge.second)].push_back(edge.first);
  }
  for (auto& n : neighbours) std::sort(n.begin(), n.end());
  return neighbours;
}

}  // namespace

SurfaceFeatures sharp_features(const TriSurface& surface, double feature_angle_deg) {
  const double cos_feature = hexdc_detail::feature_cosine("sharp_features", feature_angle_deg);
  const double cos_turn = std::cos(kCornerTurnDegrees * std::numbers::pi / 180.0);
  const std::vector<std::vector<Index>> neighbours = sharp_neighbours(surface, cos_feature);
  const std::size_t n = neighbours.size();
  const auto point = [&](Index v) { return surface.points[static_cast<std::size_t>(v)]; };
  std::vector<char> corner(n, 0);
  for (std::size_t v = 0; v < n; ++v) {
    const auto& around = neighbours[v];
    if (around.empty()) continue;
    if (around.size() != 2) {
      corner[v] = 1;
      continue;
    }
    const Vec3 in = (surface.points[v] - point(around[0])).normalized();
    const Vec3 out = (point(around[1]) - surface.points[v]).normalized();
    corner[v] = static_cast<char>(in.dot(out) < cos_turn);
  }

  SurfaceFeatures features;
  std::map<Edge, bool> used;
  // Walks from v across to `next` until a corner or the start: one crease.
  const auto trace = [&](Index start, Index next) {
    std::vector<Vec3> line{point(start)};
    Index previous = start, at = next;
    used[edge_key(previous, at)] = true;
    for (;;) {
      line.push_back(point(at));
      if (corner[static_cast<std::size_t>(at)] || at == start) break;
      const auto& around = neighbours[static_cast<std::size_t>(at)];
      const Index following = around[0] == previous ? around[1] : around[0];
      previous = at;
      at = following;
      used[edge_key(previous, at)] = true;
    }
    features.creases.push_back(std::move(line));
  };
  for (std::size_t v = 0; v < n; ++v) {
    if (!corner[v]) continue;
    features.corners.push_back(surface.points[v]);
    for (const Index w : neighbours[v])
      if (!used[edge_key(static_cast<Index>(v), w)]) trace(static_cast<Index>(v), w);
  }
  // What is left are closed loops without a corner.
  for (std::size_t v = 0; v < n; ++v)
    for (const Index w : neighbours[v])
      if (!used[edge_key(static_cast<Index>(v), w)]) trace(static_cast<Index>(v), w);
  return features;
}

}  // namespace volmesh
