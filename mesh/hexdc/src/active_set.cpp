#include "active_set.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>

#include "hex_mesh_geometry.hpp"

namespace volmesh::hexdc_detail {
namespace {

using Eigen::VectorXd;

// Adds a term's gradient in its corners to the active nodes' part of `total`.
template <std::size_t N, class Corners>
void add_gradient(const Active& a, const Corners& nodes, const std::array<Vec3, N>& gradient,
                  double scale, VectorXd& total) {
  for (std::size_t c = 0; c < N; ++c) {
    const Eigen::Index at = a.place[static_cast<std::size_t>(nodes[c])];
    if (at >= 0) total.segment<3>(at) += scale * gradient[c];
  }
}

double shortest_over_size(const Problem& p, const std::array<Vec3, 8>& corners, std::size_t h) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const auto& [u, w] : kHexEdges)
    shortest = std::min(shortest, (corners[static_cast<std::size_t>(w)] -
                                   corners[static_cast<std::size_t>(u)]).norm());
  return shortest / p.size[h];
}

// Per active hex and quad, its soft-minimum terms and gradient, and per hex its shortest edge.
struct SoftminParts {
  std::vector<SoftminTerms> hex, quad;
  std::vector<HexGradient> hex_gradient;
  std::vector<std::array<Vec3, 4>> quad_gradient;
  std::vector<double> edge;
};

SoftminParts softmin_parts(const Problem& p, const Active& a, double beta) {
  const HexMesh& mesh = p.mesh;
  const std::size_t hexes = a.hexes.size(), quads = a.quads.size();
  SoftminParts s{std::vector<SoftminTerms>(hexes), std::vector<SoftminTerms>(quads),
                 std::vector<HexGradient>(hexes), std::vector<std::array<Vec3, 4>>(quads),
                 std::vector<double>(hexes)};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, hexes, kGrain), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      const auto corners = hex_corners(mesh, a.hexes[i]);
      s.hex_gradient[i].fill(Vec3::Zero());
      s.hex[i] = hex_softmin_terms(corners, beta, s.hex_gradient[i]);
      s.edge[i] = shortest_over_size(p, corners, static_cast<std::size_t>(a.hexes[i]));
    }
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, quads, kGrain), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      s.quad_gradient[i].fill(Vec3::Zero());
      s.quad[i] = quad_softmin_terms(quad_corners(mesh, static_cast<std::size_t>(a.quads[i])), beta,
                                     s.quad_gradient[i]);
    }
  });
  return s;
}

// The frozen terms with the parts' added, in order: their least measures, and the least term
// with Σ exp(−β (q − least)) over every term.
Active::Frozen combine(const Active::Frozen& frozen, const SoftminParts& s, double beta) {
  Active::Frozen all = frozen;
  for (std::size_t i = 0; i < s.hex.size(); ++i) {
    all.least = std::min(all.least, s.hex[i].least);
    all.tet = std::min(all.tet, s.hex[i].least_tet);
    all.other = std::min(all.other, s.hex[i].other);
    all.edge = std::min(all.edge, s.edge[i]);
  }
  for (const SoftminTerms& q : s.quad) {
    all.least = std::min(all.least, q.least);
    all.other = std::min(all.other, q.other);
  }
  all.sum = frozen.sum > 0.0 ? frozen.sum * std::exp(-beta * (frozen.least - all.least)) : 0.0;
  for (const SoftminTerms& t : s.hex) all.sum += t.sum * std::exp(-beta * (t.least - all.least));
  for (const SoftminTerms& t : s.quad) all.sum += t.sum * std::exp(-beta * (t.least - all.least));
  return all;
}

}  // namespace

Active grow_active(const Problem& p, std::vector<char> marked, int rings) {
  const HexMesh& mesh = p.mesh;
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<char> next = marked;
    for (std::size_t v = 0; v < marked.size(); ++v)
      if (marked[v] != 0)
        for (const Index h : p.hexes[v])
          for (const Index u : mesh.cells[static_cast<std::size_t>(h)])
            next[static_cast<std::size_t>(u)] = 1;
    marked = std::move(next);
  }
  Active a;
  a.place.assign(mesh.points.size(), -1);
  std::vector<char> hex_at(mesh.cells.size(), 0), quad_at(mesh.boundary_faces.size(), 0);
  for (std::size_t v = 0; v < marked.size(); ++v) {
    if (marked[v] == 0 || p.kind[v] == NodeKind::fixed) continue;
    a.place[v] = static_cast<Eigen::Index>(3 * a.nodes.size());
    a.nodes.push_back(static_cast<Index>(v));
    for (const Index h : p.hexes[v]) hex_at[static_cast<std::size_t>(h)] = 1;
    for (const Index q : p.quads[v]) quad_at[static_cast<std::size_t>(q)] = 1;
  }
  for (std::size_t h = 0; h < hex_at.size(); ++h)
    if (hex_at[h] != 0) a.hexes.push_back(static_cast<Index>(h));
  for (std::size_t q = 0; q < quad_at.size(); ++q)
    if (quad_at[q] != 0) a.quads.push_back(static_cast<Index>(q));
  return a;
}

Active everything(const Problem& p) {
  Active a = grow_active(p, std::vector<char>(p.mesh.points.size(), 1), 0);
  a.hexes.resize(p.mesh.cells.size());
  std::iota(a.hexes.begin(), a.hexes.end(), Index{0});
  a.quads.resize(p.mesh.boundary_faces.size());
  std::iota(a.quads.begin(), a.quads.end(), Index{0});
  return a;
}

Evaluation barrier_energy(const Problem& p, const Active& a, const Barrier& barrier) {
  const HexMesh& mesh = p.mesh;
  const std::size_t hexes = a.hexes.size();
  std::vector<double> value(hexes), least(hexes);
  std::vector<HexGradient> gradient(hexes);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, hexes, kGrain), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      const auto h = static_cast<std::size_t>(a.hexes[i]);
      gradient[i].fill(Vec3::Zero());
      least[i] = std::numeric_limits<double>::infinity();
      value[i] = hex_barrier(hex_corners(mesh, a.hexes[i]), p.size[h], barrier, gradient[i], least[i]);
    }
  });
  Evaluation e;
  e.energy = std::accumulate(value.begin(), value.end(), 0.0);
  e.least = std::accumulate(least.begin(), least.end(), std::numeric_limits<double>::infinity(),
                            [](double x, double y) { return std::min(x, y); });
  e.gradient = VectorXd::Zero(static_cast<Eigen::Index>(3 * a.nodes.size()));
  for (std::size_t i = 0; i < hexes; ++i)
    add_gradient(a, mesh.cells[static_cast<std::size_t>(a.hexes[i])], gradient[i], 1.0, e.gradient);
  return e;
}

Evaluation softmin_energy(const Problem& p, const Active& a, double beta) {
  const HexMesh& mesh = p.mesh;
  const SoftminParts s = softmin_parts(p, a, beta);
  const Active::Frozen all = combine(a.frozen, s, beta);
  Evaluation e;
  e.least = all.tet;
  e.least_other = all.other;
  e.least_edge = all.edge;
  e.energy = -all.least + std::log(all.sum) / beta;
  e.gradient = VectorXd::Zero(static_cast<Eigen::Index>(3 * a.nodes.size()));
  const double scale = 1.0 / (beta * all.sum);
  for (std::size_t i = 0; i < s.hex.size(); ++i)
    add_gradient(a, mesh.cells[static_cast<std::size_t>(a.hexes[i])], s.hex_gradient[i],
                 scale * std::exp(-beta * (s.hex[i].least - all.least)), e.gradient);
  for (std::size_t i = 0; i < s.quad.size(); ++i)
    add_gradient(a, mesh.boundary_faces[static_cast<std::size_t>(a.quads[i])], s.quad_gradient[i],
                 scale * std::exp(-beta * (s.quad[i].least - all.least)), e.gradient);
  return e;
}

Active select_softmin(const Problem& p, double beta, double& least) {
  const HexMesh& mesh = p.mesh;
  Active all = everything(p);
  const SoftminParts s = softmin_parts(p, all, beta);
  least = combine(all.frozen, s, beta).least;
  const double span = kActiveSpan / beta;
  std::vector<char> marked(mesh.points.size(), 0);
  for (std::size_t i = 0; i < s.hex.size(); ++i)
    if (s.hex[i].least < least + span)
      for (const Index v : mesh.cells[static_cast<std::size_t>(all.hexes[i])]) marked[static_cast<std::size_t>(v)] = 1;
  for (std::size_t i = 0; i < s.quad.size(); ++i)
    if (s.quad[i].least < least + span)
      for (const Index v : mesh.boundary_faces[static_cast<std::size_t>(all.quads[i])]) marked[static_cast<std::size_t>(v)] = 1;
  Active a = grow_active(p, std::move(marked), kActiveRings);
  // The terms left out, from `s` (every hex and quad, in order).
  SoftminParts rest;
  std::size_t k = 0;
  for (std::size_t i = 0; i < s.hex.size(); ++i) {
    if (k < a.hexes.size() && a.hexes[k] == all.hexes[i]) { ++k; continue; }
    rest.hex.push_back(s.hex[i]);
    rest.edge.push_back(s.edge[i]);
  }
  k = 0;
  for (std::size_t i = 0; i < s.quad.size(); ++i) {
    if (k < a.quads.size() && a.quads[k] == all.quads[i]) { ++k; continue; }
    rest.quad.push_back(s.quad[i]);
  }
  a.frozen = combine(Active::Frozen{}, rest, beta);
  return a;
}

}  // namespace volmesh::hexdc_detail
