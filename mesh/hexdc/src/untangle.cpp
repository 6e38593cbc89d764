#include "volmesh/hexdc/untangle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "hex_mesh_geometry.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/hexdc/hex_quality.hpp"
#include "volmesh/quality/hex_metrics.hpp"

namespace volmesh {
namespace {

using namespace hexdc_detail;

// The two inner tets of kHexCornerTets (the other eight are the corner Jacobians).
constexpr std::array<std::size_t, 2> kInnerTets{4, 9};
// Their edges at the first corner are face diagonals, √2 each, in the unit cube, where 6 V = 2:
// the normalised volume 2 / (2√2) times √2 is 1.
constexpr double kInnerTetScale = std::numbers::sqrt2;
// The central-difference step of the ascent direction, of the node's shortest edge.
constexpr double kGradientStep = 1e-4;
// A node's least quality must rise by more than this to count as an improvement, so that a
// converged node is not "moved" by round-off.
constexpr double kMinGain = 1e-6;
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
  std::vector<bool> on_boundary;
};

NodeHexes link_node_hexes(const HexMesh& mesh) {
  const auto n = static_cast<std::size_t>(mesh.num_points());
  NodeHexes links{std::vector<std::vector<Index>>(n),
                  std::vector<double>(n, std::numeric_limits<double>::infinity()),
                  std::vector<bool>(n, false)};
  for (Index h = 0; h < mesh.num_cells(); ++h) {
    const auto& cell = mesh.cells[static_cast<std::size_t>(h)];
    for (const Index v : cell) links.hexes[static_cast<std::size_t>(v)].push_back(h);
    for (const auto& [a, b] : kHexEdges) {
      const auto u = static_cast<std::size_t>(cell[a]), w = static_cast<std::size_t>(cell[b]);
      const double length = (mesh.points[u] - mesh.points[w]).norm();
      links.shortest_edge[u] = std::min(links.shortest_edge[u], length);
      links.shortest_edge[w] = std::min(links.shortest_edge[w], length);
    }
  }
  for (const auto& quad : mesh.boundary_faces)
    for (const Index v : quad) links.on_boundary[static_cast<std::size_t>(v)] = true;
  return links;
}

struct HexState {
  std::vector<double> quality;
  std::vector<bool> valid;  // passes the ten corner tets
};

HexState hex_state(const HexMesh& mesh) {
  HexState state;
  for (Index h = 0; h < mesh.num_cells(); ++h) {
    const auto corners = hex_corners(mesh, h);
    state.quality.push_back(hex_shape_quality(corners));
    state.valid.push_back(hex_corner_tets_positive(corners));
  }
  return state;
}

double least(const std::vector<double>& values) {
  return *std::min_element(values.begin(), values.end());
}

Index invalid_count(const HexState& state) {
  return static_cast<Index>(std::count(state.valid.begin(), state.valid.end(), false));
}

// The least quality of node v's hexes with v at x; kFailed if a hex valid in `state` would fail
// the ten corner tets.
double least_at(HexMesh& mesh, const std::vector<Index>& hexes, std::size_t v, const Vec3& x,
                const HexState& state) {
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
  }
  mesh.points[v] = kept;
  return m;
}

// The direction in which the least quality rises fastest at x, by central differences; zero if
// it is flat there.
Vec3 ascent(HexMesh& mesh, const std::vector<Index>& hexes, std::size_t v, const Vec3& x,
            double h, const HexState& state) {
  Vec3 gradient;
  for (int a = 0; a < 3; ++a) {
    const Vec3 dx = h * Vec3::Unit(a);
    gradient[a] = least_at(mesh, hexes, v, x + dx, state) - least_at(mesh, hexes, v, x - dx, state);
  }
  return gradient.allFinite() ? gradient.normalized() : Vec3::Zero();
}

// The pattern search of node v (see the header); returns whether it moved, updating `state`.
bool optimise_node(HexMesh& mesh, const NodeHexes& links, std::size_t v, HexState& state,
                   const UntangleOptions& options) {
  const std::vector<Index>& hexes = links.hexes[v];
  const double edge = links.shortest_edge[v];
  Vec3 x = mesh.points[v];
  const double start = least_at(mesh, hexes, v, x, state);
  double best = start;
  double step = options.initial_step * edge;
  for (int k = 0; k < options.max_steps_per_node && step >= options.final_step * edge; ++k) {
    std::array<Vec3, 1 + kStencil.size()> directions{
        ascent(mesh, hexes, v, x, kGradientStep * edge, state)};
    std::copy(kStencil.begin(), kStencil.end(), directions.begin() + 1);
    Vec3 next = x;
    double gained = best;
    for (const Vec3& d : directions) {
      if (d.isZero()) continue;
      const Vec3 candidate = x + step * d;
      const double q = least_at(mesh, hexes, v, candidate, state);
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

double hex_shape_quality(const std::array<Vec3, 8>& p) {
  double quality = hex_scaled_jacobian(p);
  for (const std::size_t t : kInnerTets) {
    const auto& [a, b, c, d] = kHexCornerTets[t];
    const Vec3 e1 = p[b] - p[a], e2 = p[c] - p[a], e3 = p[d] - p[a];
    const double lengths = e1.norm() * e2.norm() * e3.norm();
    const double normalised = lengths > 0.0 ? kInnerTetScale * e1.dot(e2.cross(e3)) / lengths : 0.0;
    quality = std::min(quality, normalised);
  }
  return quality;
}

UntangleStats untangle_hexes(HexMesh& mesh, const UntangleOptions& options) {
  if (!(options.target_quality > 0.0 && options.target_quality <= 1.0))
    throw InputError("untangle_hexes: the target quality must lie in (0, 1]");
  if (options.sweeps < 0 || options.max_steps_per_node < 0)
    throw InputError("untangle_hexes: sweeps and steps must not be negative");
  if (!(options.initial_step > 0.0 && options.initial_step <= 1.0 && options.final_step > 0.0 &&
        options.final_step < options.initial_step))
    throw InputError("untangle_hexes: steps must satisfy 0 < final_step < initial_step <= 1");
  UntangleStats stats;
  if (mesh.cells.empty()) return stats;
  const NodeHexes links = link_node_hexes(mesh);
  HexState state = hex_state(mesh);
  stats.min_quality_before = least(state.quality);
  stats.invalid_hexes_before = invalid_count(state);

  std::vector<bool> active(mesh.points.size());
  for (int sweep = 0; sweep < options.sweeps; ++sweep) {
    std::fill(active.begin(), active.end(), false);
    for (Index h = 0; h < mesh.num_cells(); ++h)
      if (state.quality[static_cast<std::size_t>(h)] < options.target_quality)
        for (const Index v : mesh.cells[static_cast<std::size_t>(h)])
          active[static_cast<std::size_t>(v)] = !links.on_boundary[static_cast<std::size_t>(v)];
    Index moved = 0;
    for (std::size_t v = 0; v < active.size(); ++v)
      if (active[v] && optimise_node(mesh, links, v, state, options)) ++moved;
    ++stats.sweeps;
    stats.moves_accepted += moved;
    if (moved == 0) break;
  }
  stats.min_quality_after = least(state.quality);
  stats.invalid_hexes_after = invalid_count(state);
  return stats;
}

}  // namespace volmesh
