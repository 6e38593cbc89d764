// The PolyMesh of a pass: one cell per kept piece (whole leaves and cut pieces) in Morton
// order of the leaves, faces emitted by the leaf that owns them, points numbered by kind
// (grid vertices, edge points, face points, points inside leaves) in their own order.
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <span>

#include "assemble.hpp"

namespace volmesh::cutcell {
namespace {

struct FaceOut {
  std::size_t first = 0, size = 0;  // its loop in FaceBlock::keys
  Index owner = kNoIndex, neighbour = kNoIndex;
  bool surface = false;  // boundary face on an interface (tag from the domain's name)
  Vec3 centre = Vec3::Zero();
};

// The faces a block of leaves emits, their loops in one array: a vector per face would be a
// small allocation per face, and their frees run on one core.
struct FaceBlock {
  std::vector<PointKey> keys;
  std::vector<FaceOut> faces;
  std::span<const PointKey> loop(const FaceOut& o) const { return {keys.data() + o.first, o.size}; }
  // Starts a face whose loop the caller appends to keys, then closes with end_face.
  FaceOut& begin_face() {
    faces.emplace_back().first = keys.size();
    return faces.back();
  }
  void end_face() { faces.back().size = keys.size() - faces.back().first; }
};

// Fixed blocks of leaves: the output order does not depend on the thread count.
constexpr Index kBlock = 512;

class Assembler {
 public:
  Assembler(const Grid& grid, const std::vector<LeafCut>& cuts, const std::vector<Index>& cut_of)
      : grid_(grid), tree_(*grid.tree), cuts_(cuts), cut_of_(cut_of) {}
  PolyMesh run(AssemblyStats& stats);

 private:
  Index cell_of(Index leaf, int slot, int polygon) const {
    if (leaf == kNoIndex) return kNoIndex;
    const Index c = cut_of_[leaf];
    if (c == kNoIndex) return first_cell_[leaf] < first_cell_[leaf + 1] ? first_cell_[leaf] : kNoIndex;
    const int piece = cuts_[c].split.polygon_piece[cuts_[c].slot_polygons[slot] + polygon];
    return piece_cell_[first_piece_[c] + piece];
  }
  Vec3 position(PointKey key) const;
  PointKey leaf_point(Index cut, int local) const {
    const LeafCut& lc = cuts_[cut];
    const int inputs = static_cast<int>(lc.keys.size());
    return local < inputs ? lc.keys[local] : kCellKey + first_new_point_[cut] + (local - inputs);
  }
  void emit_leaf(Index leaf, FaceBlock& out) const;
  void emit_fine_face(Index leaf, int f, Index other, int other_slot, FaceBlock& out) const;

  const Grid& grid_;
  const Octree& tree_;
  const std::vector<LeafCut>& cuts_;
  const std::vector<Index>& cut_of_;
  std::vector<Index> first_cell_;               // per leaf, plus the total
  // Per cut leaf its pieces' cells, from first_piece_[cut]; kNoIndex for region 0.
  std::vector<Index> first_piece_, piece_cell_;
  std::vector<std::int64_t> first_new_point_;   // per cut leaf
  std::vector<Vec3> new_points_;
};

Vec3 Assembler::position(PointKey key) const {
  if (key < kEdgeKey) return grid_.position[key];
  if (key < kFaceKey) return grid_.edge_point[key - kEdgeKey].point;
  if (key < kCellKey) return grid_.results[grid_.face_result[key - kFaceKey]].contour.point;
  return new_points_[key - kCellKey];
}

void Assembler::emit_fine_face(Index leaf, int f, Index other, int other_slot,
                               FaceBlock& out) const {
  const Index face = grid_.find_face(leaf, f);
  const Index r = face == kNoIndex ? kNoIndex : grid_.face_result[face];
  if (r == kNoIndex) {  // one region over the whole face
    thread_local std::vector<Index> loop;
    loop.clear();
    leaf_face_loop(grid_.vertices, leaf, f, loop);
    if (grid_.region[loop[0]] == 0) return;
    FaceOut& o = out.begin_face();
    o.owner = cell_of(leaf, 4 * f, 0);
    o.neighbour = cell_of(other, other_slot, 0);
    out.keys.insert(out.keys.end(), loop.begin(), loop.end());
    out.end_face();
    return;
  }
  const FaceResult& result = grid_.results[r];
  const std::vector<FacePolygon>& polygons = result.contour.polygons;
  for (int k = 0; k < static_cast<int>(polygons.size()); ++k) {
    if (polygons[k].region == 0) continue;
    FaceOut& o = out.begin_face();
    o.owner = cell_of(leaf, 4 * f, k);
    o.neighbour = cell_of(other, other_slot, k);
    for (int i : polygons[k].points)
      out.keys.push_back(i < static_cast<int>(result.boundary.size()) ? result.boundary[i] : kFaceKey + face);
    out.end_face();
  }
}

void Assembler::emit_leaf(Index leaf, FaceBlock& out) const {
  for (int f = 0; f < 6; ++f) {
    const FaceNeighbours nb = tree_.face_neighbours(leaf, f);
    switch (nb.kind) {
      case FaceKind::Boundary:
        emit_fine_face(leaf, f, kNoIndex, 0, out);
        break;
      case FaceKind::Coarser: {
        const Index big = nb.leaves[0];
        const int q = quarter_of(tree_.leaf(leaf), tree_.leaf(big), f / 2);
        emit_fine_face(leaf, f, big, 4 * opposite_face(f) + q, out);
        break;
      }
      case FaceKind::Same:
        if (leaf < nb.leaves[0]) emit_fine_face(leaf, f, nb.leaves[0], 4 * opposite_face(f), out);
        break;
      case FaceKind::Finer:
        break;  // the smaller leaves emit their faces
    }
  }
  const Index c = cut_of_[leaf];
  if (c == kNoIndex) return;
  const CellSplit& split = cuts_[c].split;
  const auto interface = [&](auto points, int lower, int higher) {
    FaceOut& o = out.begin_face();
    for (int p : points) out.keys.push_back(leaf_point(c, p));
    out.end_face();
    o.owner = piece_cell_[first_piece_[c] + higher];
    o.neighbour = piece_cell_[first_piece_[c] + lower];
    if (o.neighbour == kNoIndex) {
      o.surface = true;
      for (PointKey k : out.loop(o)) o.centre += position(k) / static_cast<double>(o.size);
    }
  };
  for (const PieceTriangle& t : split.triangles) interface(t.points, t.lower, t.higher);
  for (const PiecePolygon& p : split.polygons) interface(p.points, p.lower, p.higher);
}

PolyMesh Assembler::run(AssemblyStats& stats) {
  const Index leaves = tree_.num_leaves();
  // Cells: a whole leaf in a region, or the pieces of a cut leaf outside region 0.
  first_cell_.assign(leaves + 1, 0);
  first_piece_.assign(cuts_.size() + 1, 0);
  first_new_point_.assign(cuts_.size(), 0);
  std::size_t pieces = 0, made = 0;
  for (const LeafCut& cut : cuts_) {
    pieces += cut.split.pieces.size();
    made += cut.split.new_points.size();
  }
  piece_cell_.reserve(pieces);
  new_points_.reserve(made);
  std::vector<Index> cell_region;
  std::vector<Index> cell_leaf;
  std::int64_t new_points = 0;
  for (Index i = 0; i < leaves; ++i) {
    first_cell_[i] = static_cast<Index>(cell_region.size());
    const Index c = cut_of_[i];
    if (c == kNoIndex) {
      const Index r = grid_.region[grid_.vertices.leaf_corners[i][0]];
      if (r != 0) {
        cell_region.push_back(r);
        cell_leaf.push_back(i);
      }
      continue;
    }
    const CellSplit& split = cuts_[c].split;
    first_new_point_[c] = new_points;
    new_points += static_cast<std::int64_t>(split.new_points.size());
    new_points_.insert(new_points_.end(), split.new_points.begin(), split.new_points.end());
    first_piece_[c] = static_cast<Index>(piece_cell_.size());
    for (const CellPiece& piece : split.pieces) {
      if (piece.region == 0) {
        piece_cell_.push_back(kNoIndex);
        continue;
      }
      piece_cell_.push_back(static_cast<Index>(cell_region.size()));
      cell_region.push_back(piece.region);
      cell_leaf.push_back(i);
      ++stats.cut_cells;
    }
    if (cell_region.size() > static_cast<std::size_t>(kMaxIndex))
      throw InputError("cutcell: more cells than the index limit; lower the level");
  }
  first_cell_[leaves] = static_cast<Index>(cell_region.size());
  first_piece_[cuts_.size()] = static_cast<Index>(piece_cell_.size());

  const Index blocks = (leaves + kBlock - 1) / kBlock;
  std::vector<FaceBlock> faces(blocks);
  tbb::parallel_for(Index{0}, blocks, [&](Index b) {
    for (Index i = b * kBlock; i < std::min(leaves, (b + 1) * kBlock); ++i) emit_leaf(i, faces[b]);
  });

  // Points in use, numbered by kind and then by key.
  std::vector<std::uint8_t> used_vertex(grid_.position.size(), 0), used_edge(grid_.edges.size(), 0),
      used_face(grid_.faces.size(), 0), used_new(new_points_.size(), 0);
  tbb::parallel_for(Index{0}, blocks, [&](Index b) {
    // Blocks share points: every store is of the same 1.
    const auto use = [](std::uint8_t& flag) { std::atomic_ref<std::uint8_t>(flag).store(1, std::memory_order_relaxed); };
    for (PointKey k : faces[b].keys) {
      if (k < kEdgeKey) use(used_vertex[k]);
      else if (k < kFaceKey) use(used_edge[k - kEdgeKey]);
      else if (k < kCellKey) use(used_face[k - kFaceKey]);
      else use(used_new[k - kCellKey]);
    }
  });
  PolyMesh mesh;
  std::size_t used = 0;
  for (const auto* flags : {&used_vertex, &used_edge, &used_face, &used_new})
    used += static_cast<std::size_t>(std::count(flags->begin(), flags->end(), 1));
  mesh.points.reserve(used);
  std::vector<Index> vertex_id(used_vertex.size(), kNoIndex), edge_id(used_edge.size(), kNoIndex),
      face_id(used_face.size(), kNoIndex), new_id(used_new.size(), kNoIndex);
  const auto number = [&mesh](const std::vector<std::uint8_t>& used, std::vector<Index>& id, auto pos) {
    for (std::size_t i = 0; i < used.size(); ++i)
      if (used[i]) {
        if (mesh.points.size() >= static_cast<std::size_t>(kMaxIndex))
          throw InputError("cutcell: more points than the index limit; lower the level");
        id[i] = static_cast<Index>(mesh.points.size());
        mesh.points.push_back(pos(i));
      }
  };
  number(used_vertex, vertex_id, [&](std::size_t i) { return grid_.position[i]; });
  number(used_edge, edge_id, [&](std::size_t i) { return grid_.edge_point[i].point; });
  number(used_face, face_id, [&](std::size_t i) { return grid_.results[grid_.face_result[i]].contour.point; });
  number(used_new, new_id, [&](std::size_t i) { return new_points_[i]; });
  const auto point_id = [&](PointKey k) {
    if (k < kEdgeKey) return vertex_id[k];
    if (k < kFaceKey) return edge_id[k - kEdgeKey];
    if (k < kCellKey) return face_id[k - kFaceKey];
    return new_id[k - kCellKey];
  };

  // Boundary tags: the domain's surface names, computed in parallel.
  std::vector<std::vector<std::string>> names(blocks);
  tbb::parallel_for(Index{0}, blocks, [&](Index b) {
    for (const FaceOut& o : faces[b].faces)
      if (o.surface) names[b].push_back(grid_.domain->boundary_name(o.centre));
  });
  mesh.cell_region = std::move(cell_region);
  // Tags in order of first use, then the faces written in parallel, each block at its place.
  std::vector<std::vector<Index>> tags(blocks);
  std::vector<std::size_t> first_face(blocks + 1, 0), first_key(blocks + 1, 0);
  const std::string unnamed = "boundary";
  for (Index b = 0; b < blocks; ++b) {
    std::size_t named = 0;
    for (const FaceOut& o : faces[b].faces) {
      if (o.neighbour != kNoIndex) continue;
      const std::string* name = o.surface ? &names[b][named++] : nullptr;
      tags[b].push_back(mesh.tag_index(name && !name->empty() ? *name : unnamed));
    }
    first_face[b + 1] = first_face[b] + faces[b].faces.size();
    first_key[b + 1] = first_key[b] + faces[b].keys.size();
  }
  if (first_key[blocks] > static_cast<std::size_t>(kMaxIndex))
    throw InputError("cutcell: more face vertices than the index limit; lower the level");
  const std::size_t total = first_face[blocks];
  mesh.face_offsets.resize(total + 1);
  mesh.face_offsets[total] = static_cast<Index>(first_key[blocks]);
  mesh.face_vertices.resize(first_key[blocks]);
  mesh.owner.resize(total);
  mesh.neighbour.resize(total);
  mesh.face_tag.resize(total);
  tbb::parallel_for(Index{0}, blocks, [&](Index b) {
    std::size_t f = first_face[b], key = first_key[b], tagged = 0;
    for (const FaceOut& o : faces[b].faces) {
      mesh.face_offsets[f] = static_cast<Index>(key);
      for (PointKey k : faces[b].loop(o)) mesh.face_vertices[key++] = point_id(k);
      mesh.owner[f] = o.owner;
      mesh.neighbour[f] = o.neighbour;
      mesh.face_tag[f] = o.neighbour == kNoIndex ? tags[b][tagged++] : kNoIndex;
      ++f;
    }
  });
  stats.cell_leaf = std::move(cell_leaf);
  return mesh;
}

}  // namespace

PolyMesh assemble(const Grid& grid, const std::vector<LeafCut>& cuts,
                  const std::vector<Index>& cut_of, AssemblyStats& stats) {
  return Assembler(grid, cuts, cut_of).run(stats);
}

}  // namespace volmesh::cutcell
