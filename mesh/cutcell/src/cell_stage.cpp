// M3C input of one cut leaf: its boundary as the union of the contours of its fine faces
// (a transition face contributes its four quarters), then split_cell.
#include <algorithm>
#include <string>

#include "cut_grid.hpp"

namespace volmesh::cutcell {
namespace {

class LeafInput {
 public:
  LeafInput(const Grid& grid, Index leaf) : grid_(grid), leaf_(grid.tree->leaf(leaf)) {
    for (int k = 0; k < 8; ++k) in_.corners[k] = grid.position[grid.vertices.leaf_corners[leaf][k]];
    out_.slot_polygons.fill(-1);
  }

  // Adds the fine face `face` (index into grid.faces) as slot `slot`; `outward` when its loop
  // is oriented out of this leaf.
  void add_face(Index face, int slot, bool outward);
  CellInput& input() { return in_; }
  LeafCut& cut() { return out_; }

 private:
  // The leaf's faces through grid vertex v; through both ends of the edge a split vertex splits.
  std::uint8_t vertex_faces(Index v) const {
    const auto [a, b] = grid_vertex_ends(grid_, v);
    return a == b ? octree_vertex_faces(a) : octree_vertex_faces(a) & octree_vertex_faces(b);
  }
  std::uint8_t octree_vertex_faces(Index v) const {
    const GridPoint& c = grid_.vertices.coords[v];
    std::uint8_t bits = 0;
    for (int k = 0; k < 3; ++k) {
      if (c[k] == leaf_.anchor[k]) bits |= 1 << (2 * k);
      if (c[k] == leaf_.anchor[k] + leaf_.size()) bits |= 1 << (2 * k + 1);
    }
    return bits;
  }
  int point(PointKey key, int slot_face, const FaceResult* result);

  const Grid& grid_;
  const OctreeLeaf& leaf_;
  CellInput in_;
  LeafCut out_;
};

int LeafInput::point(PointKey key, int slot_face, const FaceResult* result) {
  const auto found = std::find(out_.keys.begin(), out_.keys.end(), key);
  if (found != out_.keys.end()) return static_cast<int>(found - out_.keys.begin());
  CellPoint p;
  if (key < kEdgeKey) {
    p.position = grid_.position[key];
    p.faces = vertex_faces(static_cast<Index>(key));
  } else if (key < kFaceKey) {
    const Index e = static_cast<Index>(key - kEdgeKey);
    const auto [a, b] = grid_.edges[e];
    const EdgePoint& ep = grid_.edge_point[e];
    p.position = ep.point;
    if (ep.exact || !grid_.settings.exact)
      p.normal = grid_.region[a] < grid_.region[b] ? ep.normal : Vec3(-ep.normal);
    p.faces = vertex_faces(a) & vertex_faces(b);
    p.kind = CellPointKind::edge;
  } else {
    p.position = result->contour.point;
    p.faces = static_cast<std::uint8_t>(1 << slot_face);
    p.kind = result->contour.kind == FacePointKind::interface_point ? CellPointKind::face_interface
                                                                    : CellPointKind::face_feature;
  }
  out_.keys.push_back(key);
  in_.points.push_back(p);
  return static_cast<int>(in_.points.size()) - 1;
}

void LeafInput::add_face(Index face, int slot, bool outward) {
  const int slot_face = slot / 4;
  const int first = static_cast<int>(in_.polygons.size());
  out_.slot_polygons[slot] = first;
  const Index r = grid_.face_result[face];
  if (r == kNoIndex) {
    std::vector<Index> loop;
    leaf_face_loop(grid_.vertices, grid_.faces[face].leaf, grid_.faces[face].face, loop);
    CellPolygon poly{grid_.region[loop[0]], {}};
    for (Index v : loop) poly.points.push_back(point(v, slot_face, nullptr));
    if (!outward) std::reverse(poly.points.begin(), poly.points.end());
    in_.polygons.push_back(std::move(poly));
    return;
  }
  const FaceResult& result = grid_.results[r];
  const auto local = [&](int i) {
    const PointKey key = i < static_cast<int>(result.boundary.size()) ? result.boundary[i] : kFaceKey + face;
    return point(key, slot_face, &result);
  };
  if (result.contour.centre >= 0) in_.points[local(result.contour.centre)].junction = true;
  for (const FacePolygon& fp : result.contour.polygons) {
    CellPolygon poly{fp.region, {}};
    for (int i : fp.points) poly.points.push_back(local(i));
    if (!outward) std::reverse(poly.points.begin(), poly.points.end());
    in_.polygons.push_back(std::move(poly));
  }
  for (const ContourSegment& s : result.contour.segments) {
    CellSegment c{local(s.a), local(s.b), s.left, s.right, first + s.left_polygon, first + s.right_polygon};
    if (!outward) {
      std::swap(c.left, c.right);
      std::swap(c.left_polygon, c.right_polygon);
    }
    in_.segments.push_back(c);
  }
}

}  // namespace

LeafCut cut_leaf(const Grid& grid, Index leaf) {
  LeafCut out;
  const CellInput input = leaf_input(grid, leaf, out);
  try {
    out.split = split_cell(input, grid.settings.cell);
  } catch (const std::logic_error& e) {
    const OctreeLeaf& l = grid.tree->leaf(leaf);
    throw std::logic_error(std::string(e.what()) + " (leaf at " +
                           std::to_string(l.anchor[0]) + " " + std::to_string(l.anchor[1]) + " " +
                           std::to_string(l.anchor[2]) + ", level " + std::to_string(l.level) + ")");
  }
  return out;
}

CellInput leaf_input(const Grid& grid, Index leaf, LeafCut& cut) {
  const Octree& tree = *grid.tree;
  LeafInput input(grid, leaf);
  for (int f = 0; f < 6; ++f) {
    const FaceNeighbours nb = tree.face_neighbours(leaf, f);
    if (nb.kind == FaceKind::Finer) {
      for (int q = 0; q < 4; ++q) input.add_face(grid.find_face(nb.leaves[q], opposite_face(f)), 4 * f + q, false);
    } else if (nb.kind == FaceKind::Same && nb.leaves[0] < leaf) {
      input.add_face(grid.find_face(nb.leaves[0], opposite_face(f)), 4 * f, false);
    } else {
      input.add_face(grid.find_face(leaf, f), 4 * f, true);
    }
  }
  cut = std::move(input.cut());
  return std::move(input.input());
}

}  // namespace volmesh::cutcell
