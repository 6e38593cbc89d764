// M3C on one cell (cell_split.hpp): the stages in order (cell_split_state.hpp), the choice
// among each component's candidate triangulations by checkMesh's verdict, and the last
// resort for a face still rejected, merged with its neighbours into a polygon.
#include "cell_split.hpp"

#include "volmesh/core/geometry.hpp"
#include "volmesh/geometry/polygon_split.hpp"
#include "volmesh/quality/face_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "cell_split_state.hpp"

namespace volmesh::cutcell {
namespace {

// A face a quarter of its neighbour's area or less is a sliver: its normal means little.
constexpr double kSliverAreaRatio = 0.25;

double cell_size(const std::array<Vec3, 8>& corners) { return (corners[7] - corners[0]).norm() / std::sqrt(3.0); }

std::vector<std::uint8_t> boundary_edge_points(const CellInput& in) {
  std::vector<std::uint8_t> out(in.points.size(), 0);
  for (const CellSegment& g : in.segments)
    if (g.left == 0 || g.right == 0)
      for (const int i : {g.a, g.b})
        out[i] = in.points[i].kind == CellPointKind::edge && !in.points[i].normal.isZero();
  return out;
}

// The last resort for a face still rejected: merged with a neighbouring face of its
// component (sharing one edge, nearly coplanar unless it is a sliver) into a polygon, as
// long as that lowers its badness. The interface does not move; the trace is no longer a
// triangulation there. methods: how each component was triangulated.
void merge_skewed(SplitState& st, LoopTriangles& triangles, const std::vector<LoopMethod>& methods) {
  const std::vector<Vec3> centre = piece_centres(st, triangles);
  const double cos_limit = std::cos(st.options.merge_angle * std::acos(-1.0) / 180.0);
  for (std::size_t l = 0; l < st.loops.size(); ++l) {
    const auto [lower, higher] = st.loop_pieces(st.loops[l]);
    const bool outside = st.out.pieces[lower].region == 0;
    const bool sharp = methods[l] == LoopMethod::feature_split || methods[l] == LoopMethod::feature_fan ||
                       methods[l] == LoopMethod::interface_fan;
    const auto skew = [&](const std::vector<int>& f) { return badness(st, f, centre[higher], centre[lower], outside); };
    std::vector<std::vector<int>> faces;
    for (const Triangle& t : triangles[l]) faces.push_back({t[0], t[1], t[2]});
    for (std::size_t f = 0; f < faces.size(); ++f) {
      while (!faces[f].empty() && skew(faces[f]) > 1.0) {
        double best = skew(faces[f]);
        std::size_t best_g = faces.size();
        std::vector<int> best_union;
        const Vec3 af = polygon_geometry(st.position, std::vector<Index>(faces[f].begin(), faces[f].end())).area_vector;
        const Vec3 nf = af.normalized();
        for (std::size_t g = 0; g < faces.size(); ++g) {
          if (g == f || faces[g].empty()) continue;
          const std::vector<int> merged = merge_along_edge(faces[f], faces[g]);
          // A polygon folded over itself would fold the pieces on it.
          if (merged.empty() || split_polygon(st.position, std::vector<Index>(merged.begin(), merged.end())).folded)
            continue;
          const Vec3 ag = polygon_geometry(st.position, std::vector<Index>(faces[g].begin(), faces[g].end())).area_vector;
          // A sliver may join a face at any angle, but not across a sharp edge the component
          // keeps (a feature split or fan, or a fan around a junction), which the polygon
          // would cut off or fill in; reflex_split splits such a piece.
          if (nf.dot(ag.normalized()) < cos_limit && (sharp || af.norm() > kSliverAreaRatio * ag.norm())) continue;
          if (const double w = skew(merged); w < best) {
            best = w;
            best_g = g;
            best_union = merged;
          }
        }
        if (best_g == faces.size()) break;
        faces[f] = std::move(best_union);
        faces[best_g].clear();
      }
    }
    triangles[l].clear();
    for (std::vector<int>& f : faces) {
      if (f.size() == 3) triangles[l].push_back({f[0], f[1], f[2]});
      else if (!f.empty()) st.out.polygons.push_back({std::move(f), lower, higher, static_cast<int>(l)});
    }
  }
}

// Triangles follow the loop, whose lower label lies on the left seen from outside: their
// normals point into the lower label's piece.
void emit_triangles(SplitState& st, const LoopTriangles& triangles) {
  for (std::size_t l = 0; l < st.loops.size(); ++l) {
    const auto [lower, higher] = st.loop_pieces(st.loops[l]);
    for (const Triangle& t : triangles[l]) st.out.triangles.push_back({t, lower, higher, static_cast<int>(l)});
  }
}

}  // namespace

SplitState::SplitState(const CellInput& cell, const CellOptions& split_options)
    : in(cell), options(split_options), size(cell_size(cell.corners)), on_boundary(boundary_edge_points(cell)) {
  for (const CellPoint& p : in.points) {
    position.push_back(p.position);
    faces.push_back(p.faces);
  }
  Index material = 0;
  for (const CellPolygon& p : in.polygons) {
    if (p.region == 0) continue;
    materials_meet = materials_meet || (material != 0 && p.region != material);
    material = p.region;
  }
}

int SplitState::add_point(const Vec3& p) {
  out.new_points.push_back(p);
  position.push_back(p);
  faces.push_back(0);
  return static_cast<int>(position.size()) - 1;
}

int SplitState::fan_centre(std::span<const int> loop, const Vec3& p) {
  for (const int k : loop)
    if ((position[k] - p).norm() <= kSamePoint * size) return k;
  return add_point(p);
}

CellSplit split_cell(const CellInput& cell, const CellOptions& options) {
  SplitState st(cell, options);
  build_loops(st);
  std::vector<std::vector<Candidate>> candidates;
  for (const Loop& loop : st.loops) candidates.push_back(loop_candidates(st, loop));
  build_pieces(st);
  std::vector<std::size_t> choice(st.loops.size(), 0);
  LoopTriangles triangles;
  for (std::size_t l = 0; l < st.loops.size(); ++l) triangles.push_back(std::move(candidates[l][0].triangles));
  double worst = worst_badness(st, triangles);
  if (worst > 1.0) {
    // A face checkMesh would reject: flip slivers on flat facets, then try the
    // other triangulations, component by component, keeping any that lowers the worst.
    for (std::size_t l = 0; l < st.loops.size(); ++l) candidates[l][0].triangles = triangles[l];
    const auto chosen = [&] {
      LoopTriangles t;
      for (std::size_t l = 0; l < st.loops.size(); ++l) t.push_back(candidates[l][choice[l]].triangles);
      flip_slivers(st, t);
      return t;
    };
    triangles = chosen();
    worst = worst_badness(st, triangles);
    for (std::size_t l = 0; l < st.loops.size() && worst > 1.0; ++l)
      for (std::size_t c = 0; c < candidates[l].size(); ++c) {
        if (c == choice[l]) continue;
        const std::size_t kept = choice[l];
        choice[l] = c;
        LoopTriangles t = chosen();
        if (const double w = worst_badness(st, t); w < worst) {
          worst = w;
          triangles = std::move(t);
        } else {
          choice[l] = kept;
        }
      }
    if (worst > 1.0 && options.merge_angle > 0.0) {
      std::vector<LoopMethod> methods;
      for (std::size_t l = 0; l < st.loops.size(); ++l) methods.push_back(candidates[l][choice[l]].method);
      merge_skewed(st, triangles, methods);
      const std::vector<Vec3> centre = piece_centres(st, triangles);
      worst = worst_badness(st, triangles);
      for (const PiecePolygon& p : st.out.polygons)
        worst = std::max(worst, badness(st, p.points, centre[p.higher], centre[p.lower],
                                        st.out.pieces[p.lower].region == 0));
    }
  }
  for (std::size_t l = 0; l < st.loops.size(); ++l) st.out.loops.push_back(candidates[l][choice[l]].method);
  emit_triangles(st, triangles);
  st.out.max_badness = worst;
  return std::move(st.out);
}

// The union of two faces sharing exactly one edge (u -> v in a, v -> u in b), or empty when
// they share none or more, or the union would touch itself.
std::vector<int> merge_along_edge(const std::vector<int>& a, const std::vector<int>& b) {
  const int na = static_cast<int>(a.size()), nb = static_cast<int>(b.size());
  int shared = 0, ia = -1, ib = -1;
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j)
      if (a[i] == b[(j + 1) % nb] && a[(i + 1) % na] == b[j]) {
        ++shared;
        ia = i;
        ib = j;
      }
  if (shared != 1) return {};
  // a from v around to u, then b from u (exclusive) around to v (exclusive).
  std::vector<int> out;
  for (int k = 1; k <= na; ++k) out.push_back(a[(ia + k) % na]);
  for (int k = 2; k < nb; ++k) out.push_back(b[(ib + k) % nb]);
  std::vector<int> sorted = out;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return {};
  return out;
}

}  // namespace volmesh::cutcell
