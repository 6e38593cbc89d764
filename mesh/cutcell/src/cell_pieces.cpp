// The polygons of a cell's boundary grouped into pieces: polygons that share a piece of a
// cell edge (or of a line inside a transition face) with no contour segment along it belong
// to one piece, and each component has one piece on either side.
#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "cell_split_state.hpp"
#include "volmesh/core/geometry.hpp"

namespace volmesh::cutcell {
namespace {

std::pair<int, int> edge_key(int a, int b) { return a < b ? std::pair{a, b} : std::pair{b, a}; }

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace

void build_pieces(SplitState& st) {
  const int np = static_cast<int>(st.in.polygons.size());
  UnionFind sets(np);
  std::map<std::pair<int, int>, int> edge_polygon;
  std::vector<std::pair<int, int>> contour;
  for (const CellSegment& s : st.segments) contour.push_back(edge_key(s.a, s.b));
  std::sort(contour.begin(), contour.end());
  for (int p = 0; p < np; ++p) {
    const std::vector<int>& loop = st.in.polygons[p].points;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::pair<int, int> e = edge_key(loop[i], loop[(i + 1) % loop.size()]);
      if (std::binary_search(contour.begin(), contour.end(), e)) continue;
      const auto [it, fresh] = edge_polygon.emplace(e, p);
      if (!fresh) sets.unite(it->second, p);
    }
  }
  for (const Loop& loop : st.loops)
    for (int s : loop.segments) {
      sets.unite(st.segments[loop.segments[0]].left_polygon, st.segments[s].left_polygon);
      sets.unite(st.segments[loop.segments[0]].right_polygon, st.segments[s].right_polygon);
    }
  std::vector<int> piece_of_root(np, -1);
  st.out.polygon_piece.assign(np, -1);
  for (int p = 0; p < np; ++p) {
    const int root = sets.find(p);
    if (piece_of_root[root] < 0) {
      piece_of_root[root] = static_cast<int>(st.out.pieces.size());
      st.out.pieces.push_back({st.in.polygons[p].region, {}});
    }
    CellPiece& piece = st.out.pieces[piece_of_root[root]];
    if (piece.region != st.in.polygons[p].region)
      throw std::logic_error("split_cell: a piece joins two regions");
    piece.polygons.push_back(p);
    st.out.polygon_piece[p] = piece_of_root[root];
  }
}

// From the polygons (split around their vertex average) and the triangles.
std::vector<Vec3> piece_centres(const SplitState& st, const LoopTriangles& triangles) {
  const std::size_t n = st.out.pieces.size();
  std::vector<double> volume(n, 0.0);
  std::vector<Vec3> moment(n, Vec3::Zero());
  const Vec3 o = st.in.corners[0];
  const auto add = [&](int piece, const Vec3& a, const Vec3& b, const Vec3& c) {
    const double v = tet_volume(o, a, b, c);
    volume[piece] += v;
    moment[piece] += v * (o + a + b + c) / 4.0;
  };
  for (std::size_t p = 0; p < st.in.polygons.size(); ++p) {
    const std::vector<int>& loop = st.in.polygons[p].points;
    Vec3 mid = Vec3::Zero();
    for (int v : loop) mid += st.position[v] / static_cast<double>(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i)
      add(st.out.polygon_piece[p], st.position[loop[i]], st.position[loop[(i + 1) % loop.size()]], mid);
  }
  for (std::size_t l = 0; l < st.loops.size(); ++l) {
    const auto [lower, higher] = st.loop_pieces(st.loops[l]);
    for (const Triangle& t : triangles[l]) {
      add(higher, st.position[t[0]], st.position[t[1]], st.position[t[2]]);
      add(lower, st.position[t[0]], st.position[t[2]], st.position[t[1]]);
    }
  }
  std::vector<Vec3> centre(n);
  for (std::size_t p = 0; p < n; ++p) centre[p] = volume[p] != 0.0 ? Vec3(moment[p] / volume[p]) : o;
  return centre;
}

}  // namespace volmesh::cutcell
