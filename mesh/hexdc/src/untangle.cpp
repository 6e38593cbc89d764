#include "volmesh/hexdc/untangle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "feature_point.hpp"
#include "hex_mesh_geometry.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/hexdc/hex_quality.hpp"
#include "volmesh/quality/hex_metrics.hpp"

namespace volmesh {
namespace {

using namespace hexdc_detail;

// The central-difference step of the ascent direction, of the node's shortest edge.
constexpr double kGradientStep = 1e-4;
// A node's least quality must rise by more than this to count as an improvement, so that a
// converged node is not "moved" by round-off.
constexpr double kMinGain = 1e-6;
// Hexes whose quality is not above this fail the ten corner tets or the scaled Jacobian.
constexpr double kFailing = std::numeric_limits<double>::min();
constexpr double kFailed = -std::numeric_limits<double>::infinity();

// The 26 unit directions to the neighbours of a point in a 3x3x3 stencil: where two hexes are
// the worst at once the ascent of the least quality is not defined, and one of these usually
// raises both.
const std::array<Vec3, 26> kStencil = [] {
  std::array<Vec3, 26> directions;
  std::size_t n = 0;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x)
        if (x != 0 || y != 0 || z != 0) directions[n++] = Vec3(x, y, z).normalized();
  return directions;
}();

struct NodeHexes {
  std::vector<std::vector<Index>> hexes;  // hexes having the node as a corner
  std::vector<double> shortest_edge;
  std::vector<std::vector<Index>> quads;  // boundary quads having the node
};

NodeHexes link_node_hexes(const HexMesh& mesh) {
  const auto n = static_cast<std::size_t>(mesh.num_points());
  NodeHexes links{hexes_of_nodes(mesh),
                  std::vector<double>(n, std::numeric_limits<double>::infinity()),
                  boundary_quads_of_nodes(mesh)};
  for (Index h = 0; h < mesh.num_cells(); ++h) {
    const auto& cell = mesh.cells[static_cast<std::size_t>(h)];
    for (const auto& [a, b] : kHexEdges) {
      const auto u = static_cast<std::size_t>(cell[a]), w = static_cast<std::size_t>(cell[b]);
      const double length = (mesh.points[u] - mesh.points[w]).norm();
      links.shortest_edge[u] = std::min(links.shortest_edge[u], length);
      links.shortest_edge[w] = std::min(links.shortest_edge[w], length);
    }
  }
  return links;
}

// The least quality of node v's hexes with v at x; kFailed if a hex valid in `state` would fail
// the ten corner tets. Once it is at or below `bar` the rest of the hexes are not evaluated: the
// caller rejects such a point whatever they are.
double least_at(HexMesh& mesh, const std::vector<Index>& hexes, std::size_t v, const Vec3& x,
                const HexState& state, double bar = kFailed) {
  const Vec3 kept = mesh.points[v];
  mesh.points[v] = x;
  double m = std::numeric_limits<double>::infinity();
  for (const Index h : hexes) {
    const auto corners = hex_corners(mesh, h);
    const double q = hex_shape_quality(corners);
    if (q <= 0.0 && state.valid[static_cast<std::size_t>(h)] &&
        !hex_corner_tets_positive(corners)) {
      m = kFailed;
      break;
    }
    m = std::min(m, q);
    if (m <= bar) break;
  }
  mesh.points[v] = kept;
  return m;
}

// The direction in which `judge` (a node's least quality at a point) rises fastest at x within
// the span of `axes` (orthonormal), by central differences; zero if it is flat there.
template <class Judge>
Vec3 ascent(const Judge& judge, const Vec3& x, double h, const std::vector<Vec3>& axes) {
  Vec3 gradient = Vec3::Zero();
  for (const Vec3& a : axes) gradient += (judge(x + h * a) - judge(x - h * a)) * a;
  return gradient.allFinite() ? gradient.normalized() : Vec3::Zero();
}

// The directions a node searches: the 3x3x3 stencil inside; on the boundary the 8 directions of
// a 3x3 stencil in its tangent plane (normal to `normal`), which keeps the surface queries few.
struct SearchPattern {
  std::vector<Vec3> axes, directions;
};

SearchPattern search_pattern(const Vec3& normal) {
  if (normal.isZero())
    return {{Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()}, {kStencil.begin(), kStencil.end()}};
  const Vec3 t1 = normal.unitOrthogonal(), t2 = normal.cross(t1);
  SearchPattern pattern{{t1, t2}, {}};
  for (int a = -1; a <= 1; ++a)
    for (int b = -1; b <= 1; ++b)
      if (a != 0 || b != 0) pattern.directions.push_back((a * t1 + b * t2).normalized());
  return pattern;
}

// The pattern search of node v (see the header); returns whether it moved, updating `state`. A
// boundary node searches its tangent plane and every trial point is taken onto `surface`, or
// for a feature node onto its feature.
bool optimise_node(HexMesh& mesh, const NodeHexes& links, std::size_t v, bool feature,
                   HexState& state, const UntangleOptions& options,
                   const SurfaceProjector& surface) {
  // The worst hexes first, so that least_at stops early on a poor trial point.
  std::vector<Index> hexes = links.hexes[v];
  std::stable_sort(hexes.begin(), hexes.end(), [&](Index a, Index b) {
    return state.quality[static_cast<std::size_t>(a)] < state.quality[static_cast<std::size_t>(b)];
  });
  const double edge = links.shortest_edge[v];
  const bool on_boundary = !links.quads[v].empty();
  const SearchPattern pattern =
      search_pattern(on_boundary ? node_normal(mesh, links.quads[v]) : Vec3::Zero());
  const auto place = [&](const Vec3& p) -> Vec3 {
    if (!on_boundary) return p;
    if (!feature) return surface(p);
    const Vec3 kept = mesh.points[v];
    mesh.points[v] = p;  // feature_point reads the node's quads with the node at p
    const Vec3 placed = feature_point(mesh, links.quads[v], surface, v, edge);
    mesh.points[v] = kept;
    return placed;
  };
  const auto judge = [&](const Vec3& p) { return least_at(mesh, hexes, v, place(p), state); };
  Vec3 x = mesh.points[v];
  const double start = least_at(mesh, hexes, v, x, state);
  double best = start;
  double step = options.initial_step * edge;
  std::vector<Vec3> directions;
  for (int k = 0; k < options.max_steps_per_node && step >= options.final_step * edge; ++k) {
    directions.assign(1, ascent(judge, x, kGradientStep * edge, pattern.axes));
    directions.insert(directions.end(), pattern.directions.begin(), pattern.directions.end());
    Vec3 next = x;
    double gained = best;
    for (const Vec3& d : directions) {
      if (d.isZero()) continue;
      const Vec3 candidate = place(x + step * d);
      const double q = least_at(mesh, hexes, v, candidate, state, gained + kMinGain);
      if (q > gained + kMinGain) {
        gained = q;
        next = candidate;
        if (&d == &directions.front()) break;  // the ascent direction gains: take it
      }
    }
    if (gained > best) {
      x = next;
      best = gained;
    } else {
      step *= 0.5;
    }
  }
  if (!(best > start + kMinGain)) return false;
  mesh.points[v] = x;
  for (const Index h : hexes) {
    const auto corners = hex_corners(mesh, h);
    state.quality[static_cast<std::size_t>(h)] = hex_shape_quality(corners);
    state.valid[static_cast<std::size_t>(h)] = hex_corner_tets_positive(corners);
  }
  return true;
}

}  // namespace

UntangleStats untangle_hexes(HexMesh& mesh, const UntangleOptions& options,
                             const SurfaceProjector& surface) {
  if (!(options.target_quality > 0.0 && options.target_quality <= 1.0))
    throw InputError("untangle_hexes: the target quality must lie in (0, 1]");
  if (options.sweeps < 0 || options.max_steps_per_node < 0)
    throw InputError("untangle_hexes: sweeps and steps must not be negative");
  if (!(options.initial_step > 0.0 && options.initial_step <= 1.0 && options.final_step > 0.0 &&
        options.final_step < options.initial_step))
    throw InputError("untangle_hexes: steps must satisfy 0 < final_step < initial_step <= 1");
  const double cos_feature = feature_cosine("untangle_hexes", options.feature_angle_deg);
  UntangleStats stats;
  if (mesh.cells.empty()) return stats;
  const NodeHexes links = link_node_hexes(mesh);
  // Interior nodes move; boundary nodes only onto a given surface, feature nodes onto their
  // features there.
  std::vector<bool> movable(mesh.points.size()), feature(mesh.points.size());
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    const bool on_boundary = !links.quads[v].empty();
    movable[v] = !links.hexes[v].empty() && (!on_boundary || surface);
    feature[v] = on_boundary && surface &&
                 on_surface_feature(mesh, links.quads[v], surface, links.shortest_edge[v],
                                    cos_feature);
  }
  HexState state = hex_state(mesh, hex_shape_quality);
  stats.min_quality_before = least_quality(state);
  stats.invalid_hexes_before = invalid_count(state);

  std::vector<bool> active(mesh.points.size());
  // A node's search depends only on the nodes sharing a hex or a boundary quad with it and on
  // its feature flag: one that found no move is not searched again until one of those nodes
  // moves (its `changed` mark), since it would find none again.
  std::vector<char> changed(mesh.points.size());
  // Sweeps over the movable nodes of the hexes below `threshold`.
  const auto run_sweeps = [&](double threshold) {
    std::fill(changed.begin(), changed.end(), 1);
    for (int sweep = 0; sweep < options.sweeps; ++sweep) {
      std::fill(active.begin(), active.end(), false);
      for (Index h = 0; h < mesh.num_cells(); ++h)
        if (state.quality[static_cast<std::size_t>(h)] < threshold)
          for (const Index v : mesh.cells[static_cast<std::size_t>(h)])
            active[static_cast<std::size_t>(v)] = movable[static_cast<std::size_t>(v)];
      Index moved = 0;
      for (std::size_t v = 0; v < active.size(); ++v) {
        if (!active[v] || !changed[v]) continue;
        changed[v] = 0;
        if (!optimise_node(mesh, links, v, feature[v], state, options, surface)) continue;
        mark_around(mesh, links.hexes[v], links.quads[v], changed);
        ++moved;
      }
      ++stats.sweeps;
      stats.moves_accepted += moved;
      if (moved == 0) break;
    }
  };
  run_sweeps(options.target_quality);
  // A hex still failing whose outer quad has three corners on one crease cannot unfold while
  // they stay on it: its feature nodes are released onto the surface, which rounds the crease
  // there rather than leave the hex folded. Only the failing hexes' nodes take part.
  for (Index h = 0; h < mesh.num_cells(); ++h)
    if (!state.valid[static_cast<std::size_t>(h)])
      for (const Index v : mesh.cells[static_cast<std::size_t>(h)])
        if (feature[static_cast<std::size_t>(v)]) {
          feature[static_cast<std::size_t>(v)] = false;
          ++stats.features_released;
        }
  if (stats.features_released > 0) run_sweeps(options.target_quality);
  stats.min_quality_after = least_quality(state);
  stats.invalid_hexes_after = invalid_count(state);
  return stats;
}

}  // namespace volmesh
