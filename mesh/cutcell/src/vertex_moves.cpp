// Tiny cut cells (docs/methods.md, "Tiny cut cells"): a crossing very close to a grid vertex
// makes an arbitrarily thin piece. The vertex is moved off the interface instead, so that
// every crossing on its edges lies at least `clearance` of the edge away from it. The
// interface points stay exact crossings of the domain, so the geometry keeps its second
// order; only the grid warps.
#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <utility>

#include <oneapi/tbb/parallel_for.h>

#include "cut_grid.hpp"

namespace volmesh::cutcell {
namespace {

// A move's step: this times the clearance times the vertex's shortest edge, so that the
// vertex lands clear of the interface with a margin rather than exactly at the clearance.
constexpr double kMoveStep = 1.5;
// Crossings whose normals' cosine exceeds this (within about 2.6 degrees) lie on one plane
// for across_planes: moving across it twice would double the step.
constexpr double kSamePlaneCosine = 0.999;

// Around vertex v: the far ends of its fine edges (along each leaf edge through v, the
// nearest vertex: a midpoint when the edge has one), and the split leaf edges it ends, as
// (midpoint, far corner), which must keep a single change of region.
struct Around {
  std::vector<Index> ends;
  std::vector<std::array<Index, 2>> split_edges;
};
Around around_vertex(const Grid& grid, Index v) {
  const Octree& tree = *grid.tree;
  const OctreeVertices& verts = grid.vertices;
  const LeavesAround around = leaves_around(tree, verts.coords[v]);
  const std::span<const Index> leaves(around.leaf.data(), around.count);
  Around out;
  const auto add = [&out, v](Index w) {
    if (w != kNoIndex && w != v && std::find(out.ends.begin(), out.ends.end(), w) == out.ends.end())
      out.ends.push_back(w);
  };
  for (Index leaf : leaves) {
    for (int e = 0; e < 12; ++e) {
      const Index a = verts.leaf_corners[leaf][kEdgeCorners[e][0]];
      const Index b = verts.leaf_corners[leaf][kEdgeCorners[e][1]];
      const Index m = verts.leaf_edge_mid[leaf][e];
      if (a == v) add(m != kNoIndex ? m : b);
      if (b == v) add(m != kNoIndex ? m : a);
      if (m != kNoIndex && (a == v || b == v)) out.split_edges.push_back({m, a == v ? b : a});
      if (m == v) {
        add(a);
        add(b);
      }
    }
  }
  return out;
}

// x moved out across the tangent planes of these crossings (normals pointing out), to `step`
// beyond each: across every pair of distinct planes, then across all of them when there are
// more (a box's corner: across two faces the vertex is already outside, and its leaves' faces
// stay clear of the third). None unless there are two distinct normals.
std::vector<Vec3> across_planes(const Vec3& x, const std::vector<Crossing>& crossings, double step) {
  std::vector<const Crossing*> planes;
  for (const Crossing& c : crossings)
    if (std::none_of(planes.begin(), planes.end(),
                     [&c](const Crossing* p) { return p->normal.dot(c.normal) > kSamePlaneCosine; }))
      planes.push_back(&c);
  const auto across = [&x, step](std::span<const Crossing* const> set) {
    Vec3 p = x;
    for (const Crossing* c : set) p += ((c->point - x).dot(c->normal) + step) * c->normal;
    return p;
  };
  std::vector<Vec3> out;
  if (planes.size() < 2) return out;
  for (std::size_t i = 0; i < planes.size(); ++i)
    for (std::size_t j = i + 1; j < planes.size(); ++j) out.push_back(across(std::array{planes[i], planes[j]}));
  if (planes.size() > 2) out.push_back(across(planes));
  return out;
}

struct Nearest {
  double fraction = 1.0;  // of the edge, from v
  Crossing crossing;
  bool found = false;
};

class Mover {
 public:
  Mover(Grid& grid, double clearance) : grid_(grid), clearance_(clearance) {}
  std::array<Index, 2> run();

 private:
  enum State : std::uint8_t { none, pending, done };
  std::vector<Crossing> transversal(const Vec3& a, const Vec3& b) const {
    std::vector<Crossing> out = grid_.domain->crossings(a, b);
    out.erase(std::remove_if(out.begin(), out.end(), [](const Crossing& c) { return c.before == c.after; }),
              out.end());
    return out;
  }
  double clearance_at(const Vec3& p, Index region, const Around& around,
                      const std::vector<double>& far_before,
                      const std::vector<std::size_t>& crossings_before) const;
  bool move(Index v, const Around& around);

  Grid& grid_;
  double clearance_;
  std::vector<State> state_;
};

// The clearance a position p (region `region`) leaves: the smallest fraction of an edge at v
// between p, or a far end that is not still to be moved, and a crossing; negative when an edge
// would be crossed other than its end regions require (none, or once between them) and more
// often than before the move (an edge through a junction, or a layer thinner than the cell,
// may already be crossed twice), or a split leaf edge would change region twice.
double Mover::clearance_at(const Vec3& p, Index region, const Around& around,
                           const std::vector<double>& far_before,
                           const std::vector<std::size_t>& crossings_before) const {
  for (const auto& [m, far] : around.split_edges)
    if (region != grid_.region[m] && grid_.region[m] != grid_.region[far]) return -1.0;
  double clear = 1.0;
  const std::vector<Index>& ends = around.ends;
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const Index w = ends[k];
    const std::vector<Crossing> hits = transversal(p, grid_.position[w]);
    const std::size_t required = region == grid_.region[w] ? 0 : 1;
    if (hits.size() != required && (hits.size() < required || hits.size() > crossings_before[k])) return -1.0;
    if (hits.empty()) continue;
    clear = std::min(clear, hits.front().t);
    const double far = 1.0 - hits.back().t;
    if (far < clearance_ && far < far_before[k] && state_[w] != pending) clear = std::min(clear, far);
  }
  return clear;
}

bool Mover::move(Index v, const Around& around) {
  const std::vector<Index>& ends = around.ends;
  const Vec3 x = grid_.position[v];
  Nearest nearest;
  std::vector<Crossing> near_boundary;  // crossings into the outside within the clearance
  std::vector<double> far_before(ends.size(), 1.0);
  std::vector<std::size_t> crossings_before(ends.size(), 0);
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const Vec3& y = grid_.position[ends[k]];
    shortest = std::min(shortest, (y - x).norm());
    const std::vector<Crossing> hits = transversal(x, y);
    if (hits.empty()) continue;
    far_before[k] = 1.0 - hits.back().t;
    crossings_before[k] = hits.size();
    if (grid_.region[ends[k]] == grid_.region[v]) continue;
    if (hits.front().t < clearance_ && hits.front().after == 0) near_boundary.push_back(hits.front());
    if (!nearest.found || hits.front().t < nearest.fraction) nearest = {hits.front().t, hits.front(), true};
  }
  if (!nearest.found || nearest.fraction >= clearance_) return true;

  // Off the interface along its normal (which points from v's side into the other region):
  // across it when that leaves the vertex outside, so that the kept pieces grow, otherwise
  // away from it. A midpoint vertex keeps its region (its leaf edge would change region
  // twice). Next to a junction no such move may clear every interface: then farther and
  // nearer moves and moves along the axes, keeping the one that clears the most.
  const Vec3 n = nearest.crossing.normal;
  const Vec3& at = nearest.crossing.point;
  const double step = kMoveStep * clearance_ * shortest;
  const Index own = grid_.region[v], other = nearest.crossing.after;
  const bool hanging = grid_.vertices.hanging[v] != 0;
  const double first = other == 0 && own != 0 && !hanging ? 1.0 : -1.0;
  // Next to a sharp edge or corner of the boundary, when the moves across the nearest face
  // fail: out across two of its faces at once, then all, clear of each (across_planes). The
  // diagonal steps below may only just cross the edge and leave it in a corner of the leaves'
  // faces, too close for a feature point, and the edge is cut off.
  std::vector<Vec3> candidates{at + first * step * n, at - first * step * n};
  if (first > 0.0)
    for (const Vec3& p : across_planes(x, near_boundary, step)) candidates.push_back(p);
  for (const double scale : {0.5, 2.0})
    for (const double side : {-1.0, 1.0}) candidates.push_back(at + side * scale * step * n);
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {-1.0, 1.0}) candidates.push_back(x + side * step * Vec3::Unit(axis));
  // Where several interfaces meet (a plane through a sphere), away from all of them: the
  // diagonal directions, then twice as far.
  for (const double scale : {1.0, 2.0})
    for (int k = 0; k < 27; ++k) {
      const Vec3 d(k % 3 - 1, k / 3 % 3 - 1, k / 9 - 1);
      if ((scale == 1.0 && d.cwiseAbs().sum() < 2.0) || d.isZero()) continue;
      candidates.push_back(x + scale * step * d.normalized());
    }
  // A vertex on the root's boundary stays on it: the mesh's outer faces stay the root's.
  const GridPoint& c = grid_.vertices.coords[v];
  for (int k = 0; k < 3; ++k)
    if (c[k] == 0 || c[k] == kOctreeGrid)
      for (Vec3& p : candidates) p[k] = x[k];
  double best = nearest.fraction;
  bool resolved = false;
  std::optional<std::pair<Vec3, Index>> chosen;
  for (const Vec3& p : candidates) {
    const Index region = grid_.domain->region(p);
    if (hanging && region != own) continue;
    const double clear = clearance_at(p, region, around, far_before, crossings_before);
    if (clear >= clearance_) {
      chosen = {p, region};
      resolved = true;
      break;
    }
    if (clear > best) {
      best = clear;
      chosen = {p, region};
    }
  }
  if (chosen) {
    grid_.position[v] = chosen->first;
    grid_.region[v] = chosen->second;
  }
  return resolved;
}

// The pending vertices are moved in index order, each seeing the moves of those before it.
// Two of them interact only through the vertices around them (their edges' far ends and the
// far corners of their split edges), so they are moved in parallel waves: a vertex
// waits for the wave after the last of its interacting vertices with a lower index. The
// result is the sequential one, for any number of threads.
std::array<Index, 2> Mover::run() {
  state_.assign(grid_.position.size(), none);
  for (std::size_t e = 0; e < grid_.edges.size(); ++e) {
    const auto [a, b] = grid_.edges[e];
    if (grid_.region[a] == grid_.region[b]) continue;
    const Vec3 &pa = grid_.position[a], &pb = grid_.position[b];
    const double t = (grid_.edge_point[e].point - pa).dot(pb - pa) / (pb - pa).squaredNorm();
    if (t < clearance_) state_[a] = pending;
    if (t > 1.0 - clearance_) state_[b] = pending;
  }
  std::vector<Index> pending_vertices;
  for (Index v = 0; v < static_cast<Index>(state_.size()); ++v)
    if (state_[v] == pending) pending_vertices.push_back(v);
  const std::size_t n = pending_vertices.size();
  std::vector<Around> around(n);
  tbb::parallel_for(std::size_t{0}, n,
                    [&](std::size_t k) { around[k] = around_vertex(grid_, pending_vertices[k]); });

  // Interactions between pending vertices, both ways, as pairs of positions in the list.
  std::vector<Index> slot(state_.size(), kNoIndex);
  for (std::size_t k = 0; k < n; ++k) slot[pending_vertices[k]] = static_cast<Index>(k);
  std::vector<std::pair<Index, Index>> pairs;
  for (std::size_t k = 0; k < n; ++k) {
    const auto link = [&](Index w) {
      if (slot[w] != kNoIndex && slot[w] != static_cast<Index>(k))
        pairs.emplace_back(std::max<Index>(k, slot[w]), std::min<Index>(k, slot[w]));
    };
    for (Index w : around[k].ends) link(w);
    for (const auto& [m, far] : around[k].split_edges) link(far);
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<Index> wave(n, 0);
  for (const auto& [later, earlier] : pairs) wave[later] = std::max(wave[later], wave[earlier] + 1);
  std::vector<std::vector<Index>> waves;
  for (std::size_t k = 0; k < n; ++k) {
    if (static_cast<std::size_t>(wave[k]) >= waves.size()) waves.resize(wave[k] + 1);
    waves[wave[k]].push_back(static_cast<Index>(k));
  }

  std::vector<char> resolved(n, 1), changed(n, 0);
  for (const std::vector<Index>& members : waves) {
    tbb::parallel_for(std::size_t{0}, members.size(), [&](std::size_t i) {
      const Index k = members[i], v = pending_vertices[k];
      const Vec3 before = grid_.position[v];
      resolved[k] = move(v, around[k]);
      changed[k] = grid_.position[v] != before;
    });
    for (Index k : members) state_[pending_vertices[k]] = done;
  }
  Index moved = 0, unresolved = 0;
  for (std::size_t k = 0; k < n; ++k) {
    moved += changed[k];
    unresolved += !resolved[k];
  }
  return {moved, unresolved};
}

}  // namespace

std::array<Index, 2> move_vertices(Grid& grid, double clearance) { return Mover(grid, clearance).run(); }

}  // namespace volmesh::cutcell
