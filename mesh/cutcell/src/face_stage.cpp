// The fine faces of the cut leaves and M3S on each face whose vertices lie in several
// regions. A face is contoured once, from the leaf that owns it, so both sides share it.
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_sort.h>

#include <algorithm>
#include <numeric>
#include <optional>

#include "cut_grid.hpp"

namespace volmesh::cutcell {
namespace {

std::uint64_t face_code(Index leaf, int face) { return std::uint64_t(leaf) * 6 + std::uint64_t(face); }

// The fine faces on the six sides of a leaf.
void fine_faces_of(const Octree& tree, Index leaf, std::vector<FineFace>& out) {
  for (int f = 0; f < 6; ++f) {
    const FaceNeighbours nb = tree.face_neighbours(leaf, f);
    const auto face = static_cast<std::int8_t>(f), back = static_cast<std::int8_t>(opposite_face(f));
    switch (nb.kind) {
      case FaceKind::Boundary:
        out.push_back({leaf, face, kNoIndex, 0, 0});
        break;
      case FaceKind::Coarser: {
        const Index big = nb.leaves[0];
        const auto q = static_cast<std::int8_t>(quarter_of(tree.leaf(leaf), tree.leaf(big), f / 2));
        out.push_back({leaf, face, big, back, q});
        break;
      }
      case FaceKind::Same:
        if (leaf < nb.leaves[0])
          out.push_back({leaf, face, nb.leaves[0], back, 0});
        else
          out.push_back({nb.leaves[0], back, leaf, face, 0});
        break;
      case FaceKind::Finer:
        for (int q = 0; q < 4; ++q) out.push_back({nb.leaves[q], back, leaf, face, static_cast<std::int8_t>(q)});
        break;
    }
  }
}

std::optional<FaceResult> contour(const Grid& grid, const FineFace& face) {
  std::vector<Index> loop;
  leaf_face_loop(grid.vertices, face.leaf, face.face, loop);
  const Index r0 = grid.region[loop[0]];
  if (std::all_of(loop.begin(), loop.end(), [&](Index v) { return grid.region[v] == r0; }))
    return std::nullopt;
  FaceResult result;
  FaceInput input;
  input.on_root = face.other == kNoIndex;
  int corner = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Index u = loop[i], w = loop[(i + 1) % loop.size()];
    // leaf_face_loop lists corner k, then the midpoint of edge k if there is one.
    if (corner < 4 && u == grid.vertices.leaf_corners[face.leaf][kFaceCorners[face.face][corner]])
      input.corners[corner++] = static_cast<int>(input.boundary.size());
    const auto add_vertex = [&](Index v) {
      input.boundary.push_back({grid.position[v], grid.region[v], Vec3::Zero()});
      result.boundary.push_back(v);
    };
    const auto add_edge_point = [&](Index from, Index to) {
      const Index e = grid.find_edge(from, to);
      const EdgePoint& p = grid.edge_point[e];
      const Vec3 normal = grid.settings.exact && !p.exact ? Vec3::Zero() : p.normal;
      input.boundary.push_back({p.point, kNoIndex, from < to ? normal : Vec3(-normal), p.pinched});
      result.boundary.push_back(kEdgeKey + e);
    };
    add_vertex(u);
    if (grid.region[u] == grid.region[w]) continue;
    if (const Index x = grid.split_vertex[grid.find_edge(u, w)]; x != kNoIndex) {
      add_edge_point(u, x);
      add_vertex(x);
      add_edge_point(x, w);
    } else {
      add_edge_point(u, w);
    }
  }
  result.contour = contour_face(input, grid.settings.face);
  return result;
}

// The fine edges along a face whose ends lie in different regions.
std::vector<Index> changing_edges(const Grid& grid, const FineFace& face) {
  std::vector<Index> loop, out;
  leaf_face_loop(grid.vertices, face.leaf, face.face, loop);
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Index u = loop[k], w = loop[(k + 1) % loop.size()];
    if (grid.region[u] != grid.region[w]) out.push_back(grid.find_edge(u, w));
  }
  return out;
}

// Edge e's split undone: its one crossing stands for both again, the split vertex's region
// pinched out beside it.
void leave_whole(Grid& grid, Index e) {
  if (const Index x = grid.split_vertex[e]; x != kNoIndex) {
    grid.edge_point[e].pinched = grid.region[x];
    grid.split_vertex[e] = kNoIndex;
  }
}

// M3S takes at most four interface points on a face: the edges of a face that their split
// vertices would give more are left whole. Counted before any is undone, so the result
// does not depend on the order.
void keep_faces_contourable(Grid& grid) {
  if (grid.split_edge.empty()) return;
  std::vector<std::uint8_t> too_many(grid.faces.size(), 0);
  tbb::parallel_for(std::size_t{0}, grid.faces.size(), [&](std::size_t i) {
    int points = 0;
    for (const Index e : changing_edges(grid, grid.faces[i])) points += grid.split_vertex[e] != kNoIndex ? 2 : 1;
    too_many[i] = points > 4;
  });
  for (std::size_t i = 0; i < grid.faces.size(); ++i)
    if (too_many[i])
      for (const Index e : changing_edges(grid, grid.faces[i])) leave_whole(grid, e);
}

// Split vertices that a polygon of the contour holds with their two crossings alone.
std::vector<PointKey> lens_vertices(const Grid& grid, const FaceResult& result) {
  std::vector<PointKey> out;
  const auto n = static_cast<int>(result.boundary.size());
  const Index first_split = grid.vertices.num_vertices();
  for (const FacePolygon& poly : result.contour.polygons) {
    if (poly.points.size() != 3 ||
        !std::all_of(poly.points.begin(), poly.points.end(), [n](int i) { return i < n; }))
      continue;
    for (int k = 0; k < 3; ++k) {
      const PointKey x = result.boundary[poly.points[k]];
      if (x < first_split || x >= kEdgeKey) continue;
      const auto [a, b] = grid.edges[grid.split_edge[x - first_split]];
      const PointKey to_a = kEdgeKey + grid.find_edge(a, static_cast<Index>(x));
      const PointKey to_b = kEdgeKey + grid.find_edge(b, static_cast<Index>(x));
      const PointKey before = result.boundary[poly.points[(k + 2) % 3]];
      const PointKey after = result.boundary[poly.points[(k + 1) % 3]];
      if ((before == to_a && after == to_b) || (before == to_b && after == to_a)) out.push_back(x);
    }
  }
  return out;
}

}  // namespace

void contour_faces(Grid& grid) {
  const Octree& tree = *grid.tree;
  std::vector<Index> cut_leaves;
  for (Index i = 0; i < tree.num_leaves(); ++i)
    if (grid.cut[i]) cut_leaves.push_back(i);
  std::vector<std::vector<FineFace>> per_leaf(cut_leaves.size());
  tbb::parallel_for(std::size_t{0}, cut_leaves.size(),
                    [&](std::size_t k) { fine_faces_of(tree, cut_leaves[k], per_leaf[k]); });
  std::vector<FineFace> faces;
  for (const auto& list : per_leaf) faces.insert(faces.end(), list.begin(), list.end());
  // A face listed from both sides is listed alike: which copy stays does not matter.
  tbb::parallel_sort(faces.begin(), faces.end(), [](const FineFace& a, const FineFace& b) {
    return face_code(a.leaf, a.face) < face_code(b.leaf, b.face);
  });
  faces.erase(std::unique(faces.begin(), faces.end(),
                          [](const FineFace& a, const FineFace& b) { return a.leaf == b.leaf && a.face == b.face; }),
              faces.end());
  grid.faces = std::move(faces);
  grid.first_face.assign(tree.num_leaves() + 1, 0);
  for (const FineFace& face : grid.faces) ++grid.first_face[face.leaf + 1];
  std::partial_sum(grid.first_face.begin(), grid.first_face.end(), grid.first_face.begin());

  keep_faces_contourable(grid);
  std::vector<std::optional<FaceResult>> results(grid.faces.size());
  std::vector<std::size_t> todo(grid.faces.size());
  std::iota(todo.begin(), todo.end(), std::size_t{0});
  while (!todo.empty()) {
    tbb::parallel_for(std::size_t{0}, todo.size(),
                      [&](std::size_t k) { results[todo[k]] = contour(grid, grid.faces[todo[k]]); });
    // A split vertex whose two crossings a face joins by a chord along the edge would leave
    // a polygon of no area: that edge is left whole, its faces contoured again.
    std::vector<PointKey> unsplit;
    for (const std::size_t i : todo)
      if (results[i])
        for (const PointKey x : lens_vertices(grid, *results[i])) unsplit.push_back(x);
    if (unsplit.empty()) break;
    for (const PointKey x : unsplit) leave_whole(grid, grid.split_edge[x - grid.vertices.num_vertices()]);
    std::sort(unsplit.begin(), unsplit.end());
    todo.clear();
    for (std::size_t i = 0; i < results.size(); ++i)
      if (results[i] &&
          std::any_of(results[i]->boundary.begin(), results[i]->boundary.end(),
                      [&](PointKey k) { return std::binary_search(unsplit.begin(), unsplit.end(), k); }))
        todo.push_back(i);
  }
  grid.face_result.assign(grid.faces.size(), kNoIndex);
  grid.results.clear();
  for (std::size_t i = 0; i < results.size(); ++i)
    if (results[i]) {
      grid.face_result[i] = static_cast<Index>(grid.results.size());
      grid.results.push_back(std::move(*results[i]));
    }
}

std::vector<Index> leaves_for_face_points(const Grid& grid, int max_level) {
  const Octree& tree = *grid.tree;
  std::vector<std::uint8_t> flag(tree.num_leaves(), 0);
  for (std::size_t i = 0; i < grid.faces.size(); ++i) {
    const Index r = grid.face_result[i];
    if (r == kNoIndex || !grid.results[r].contour.point_left_face) continue;
    for (const Index leaf : {grid.faces[i].leaf, grid.faces[i].other})
      if (leaf != kNoIndex && tree.leaf(leaf).level < max_level) flag[leaf] = 1;
  }
  // A transition face holds at most one face interface point: its leaf is split otherwise.
  for (const FineFace& face : grid.faces) {
    if (face.other == kNoIndex || tree.leaf(face.other).level == tree.leaf(face.leaf).level) continue;
    int points = 0;
    const FaceNeighbours nb = tree.face_neighbours(face.other, face.other_face);
    for (const Index small : nb.leaves) {
      const Index f = grid.find_face(small, opposite_face(face.other_face));
      const Index r = f == kNoIndex ? kNoIndex : grid.face_result[f];
      points += r != kNoIndex && grid.results[r].contour.kind == FacePointKind::interface_point;
    }
    if (points > 1) flag[face.other] = 1;
  }
  std::vector<Index> out;
  for (Index i = 0; i < tree.num_leaves(); ++i)
    if (flag[i]) out.push_back(i);
  return out;
}

}  // namespace volmesh::cutcell
