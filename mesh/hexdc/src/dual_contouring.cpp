#include "volmesh/hexdc/dual_contouring.hpp"

#include <algorithm>
#include <bit>
#include <optional>
#include <string>

#include "node_crossings.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/hexdc/hex_quality.hpp"

namespace volmesh {
namespace {

constexpr Index kRegion = 1;

// k with dims = 2^k + 1 on every axis; throws InputError otherwise.
int grid_depth(const VoxelGrid& field) {
  const auto& d = field.dims;
  const auto dims_text = std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" +
                         std::to_string(d[2]);
  if (d[0] != d[1] || d[0] != d[2])
    throw InputError("hexdc: grid " + dims_text + " is not cubic; the octree needs dim^3 samples");
  for (int k = 1; k <= kHexdcMaxDepth; ++k)
    if (d[0] == (Index{1} << k) + 1) return k;
  throw InputError("hexdc: grid " + dims_text + ": dim " + std::to_string(d[0]) +
                   " is not 2^k + 1 with 1 <= k <= " + std::to_string(kHexdcMaxDepth));
}

enum class NodeKind { outside, boundary, interior };

// Outside: no sample >= 0; interior: all >= 0; boundary: both signs.
NodeKind classify_node(const VoxelGrid& field, const std::array<Index, 3>& lo, Index size) {
  bool any_inside = false, any_outside = false;
  for (Index k = lo[2]; k <= lo[2] + size; ++k)
    for (Index j = lo[1]; j <= lo[1] + size; ++j)
      for (Index i = lo[0]; i <= lo[0] + size; ++i)
        (field.at(i, j, k) >= 0.0f ? any_inside : any_outside) = true;
  if (!any_inside) return NodeKind::outside;
  return any_outside ? NodeKind::boundary : NodeKind::interior;
}


// The 2x2x2 blocks of nodes, present where a hex is made.
struct BlockSet {
  Index per_axis = 0;
  std::vector<char> present;
  std::size_t id(Index i, Index j, Index k) const {
    return static_cast<std::size_t>(i + per_axis * (j + per_axis * k));
  }
};

// The eight blocks around a node are its octants, octant o = a + 2b + 4c at block offset
// (a, b, c) - 1; two octants share a face when they differ in one bit.
constexpr int kOctants = 8;

// The face-connected components of the octants in `mask`, each as a mask, lowest octant first.
std::vector<unsigned> octant_components(unsigned mask) {
  std::vector<unsigned> components;
  for (int o = 0; o < kOctants; ++o) {
    const unsigned bit = 1u << o;
    if (!(mask & bit)) continue;
    unsigned component = bit;
    for (unsigned grown = 0; grown != component;) {
      grown = component;
      for (int p = 0; p < kOctants; ++p)
        if (grown & (1u << p))
          for (int axis = 0; axis < 3; ++axis) component |= (1u << (p ^ (1 << axis))) & mask;
    }
    components.push_back(component);
    mask &= ~component;
  }
  return components;
}

// The octants to remove at a node with present octants `filled` so that the boundary there is
// a manifold: none when the present and the absent octants are each face-connected. Present
// octants in several components (hexes meeting at an edge or a vertex only) keep the largest
// component (the first of equals); absent octants in several (the outside pinched to a point or
// an edge) are joined by removing the present octants on the path that flips the bits of the
// first absent component's lowest octant toward the second's, x first.
unsigned octants_to_remove(unsigned filled) {
  constexpr unsigned kAll = (1u << kOctants) - 1;
  const std::vector<unsigned> present = octant_components(filled);
  if (present.size() > 1) {
    const auto largest = std::max_element(
        present.begin(), present.end(),
        [](unsigned a, unsigned b) { return std::popcount(a) < std::popcount(b); });
    return filled & ~*largest;
  }
  const std::vector<unsigned> absent = octant_components(kAll & ~filled);
  if (absent.size() <= 1) return 0;
  unsigned from = static_cast<unsigned>(std::countr_zero(absent[0]));
  const auto to = static_cast<unsigned>(std::countr_zero(absent[1]));
  unsigned removed = 0;
  for (int axis = 0; axis < 3; ++axis)
    if ((from ^ to) & (1u << axis)) {
      from ^= 1u << axis;
      removed |= (1u << from) & filled;
    }
  return removed;
}

// Removes blocks until the boundary of the present ones is a manifold at every node, so that
// each boundary node has one fan of boundary quads, a disc, and an inward direction (the
// pillow layer and smoothing need one). Nodes are visited in index order until none changes,
// which makes the result deterministic. Returns the blocks removed.
Index make_manifold(BlockSet& blocks) {
  const Index m = blocks.per_axis;
  Index removed = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (Index k = 0; k <= m; ++k)
      for (Index j = 0; j <= m; ++j)
        for (Index i = 0; i <= m; ++i) {
          // Octant (a, b, c) of node (i, j, k) is block (i - 1 + a, j - 1 + b, k - 1 + c).
          const auto octant_block = [&](int o) -> std::optional<std::size_t> {
            const Index bi = i - 1 + (o & 1), bj = j - 1 + ((o >> 1) & 1), bk = k - 1 + (o >> 2);
            if (bi < 0 || bj < 0 || bk < 0 || bi >= m || bj >= m || bk >= m) return std::nullopt;
            return blocks.id(bi, bj, bk);
          };
          unsigned filled = 0;
          for (int o = 0; o < kOctants; ++o)
            if (const auto b = octant_block(o); b && blocks.present[*b]) filled |= 1u << o;
          const unsigned remove = octants_to_remove(filled);
          for (int o = 0; o < kOctants; ++o)
            if (remove & (1u << o)) {
              blocks.present[*octant_block(o)] = 0;
              ++removed;
              changed = true;
            }
        }
  }
  return removed;
}

}  // namespace

PolyMesh hexdc_uniform(const VoxelGrid& field, int level, HexdcStats* stats) {
  const int depth = grid_depth(field);
  if (level < 1 || level > depth)
    throw InputError("hexdc: level " + std::to_string(level) + " outside [1, " +
                     std::to_string(depth) + "] for a grid of " + std::to_string(field.dims[0]) +
                     "^3 samples");
  if (std::none_of(field.values.begin(), field.values.end(), [](float f) { return f >= 0.0f; }))
    throw InputError("hexdc: no sample >= 0 in the field; nothing is inside");

  HexdcStats s;
  const Index n = Index{1} << level;             // nodes per axis
  const Index size = Index{1} << (depth - level);  // voxels per node side
  s.nodes_per_axis = n;
  const auto node_id = [n](Index i, Index j, Index k) { return i + n * (j + n * k); };

  HexMesh hexes;
  std::vector<Index> vertex(static_cast<std::size_t>(n) * n * n, kNoIndex);
  for (Index k = 0; k < n; ++k)
    for (Index j = 0; j < n; ++j)
      for (Index i = 0; i < n; ++i) {
        const std::array<Index, 3> lo{i * size, j * size, k * size};
        const NodeKind kind = classify_node(field, lo, size);
        if (kind == NodeKind::outside) continue;
        const Vec3 low = field.point(lo[0], lo[1], lo[2]);
        const Vec3 high = field.point(lo[0] + size, lo[1] + size, lo[2] + size);
        Vec3 point = 0.5 * (low + high);
        if (kind == NodeKind::boundary) {
          const QefVertex q =
              solve_qef(node_crossings(field, lo, size), Eigen::AlignedBox3d(low, high));
          point = q.point;
          ++s.boundary_vertices;
          if (q.fell_back) ++s.qef_fallbacks;
        } else {
          ++s.interior_vertices;
        }
        vertex[node_id(i, j, k)] = hexes.num_points();
        hexes.points.push_back(point);
      }

  // VTK corner c of the block at (i, j, k): offsets x, y as 0-3 counter-clockwise, z by c / 4.
  constexpr std::array<std::array<Index, 3>, 8> kCornerOffset{
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  const Index m = n - 1;  // blocks per axis
  BlockSet blocks{m, std::vector<char>(static_cast<std::size_t>(m) * m * m, 0)};
  for (Index k = 0; k < m; ++k)
    for (Index j = 0; j < m; ++j)
      for (Index i = 0; i < m; ++i)
        blocks.present[blocks.id(i, j, k)] = std::all_of(
            kCornerOffset.begin(), kCornerOffset.end(), [&](const std::array<Index, 3>& o) {
              return vertex[node_id(i + o[0], j + o[1], k + o[2])] != kNoIndex;
            });
  s.nonmanifold_blocks_removed = make_manifold(blocks);

  std::vector<char> used(hexes.points.size(), 0);
  for (Index k = 0; k < m; ++k)
    for (Index j = 0; j < m; ++j)
      for (Index i = 0; i < m; ++i) {
        if (!blocks.present[blocks.id(i, j, k)]) continue;
        std::array<Index, 8> cell{};
        std::array<Vec3, 8> corners;
        for (std::size_t c = 0; c < 8; ++c) {
          const auto& o = kCornerOffset[c];
          cell[c] = vertex[node_id(i + o[0], j + o[1], k + o[2])];
          corners[c] = hexes.points[cell[c]];
        }
        if (!hex_corner_tets_positive(corners)) ++s.invalid_hexes;
        for (const Index v : cell) used[v] = 1;
        hexes.cells.push_back(cell);
      }
  s.hexes = hexes.num_cells();
  if (s.hexes == 0)
    throw InputError("hexdc: no 2x2x2 block of neighbouring inside nodes at level " +
                     std::to_string(level) + "; no hex to build (try a finer level)");

  // Renumber the vertices that some hex uses, in their order.
  std::vector<Index> renumber(hexes.points.size(), kNoIndex);
  std::vector<Vec3> kept;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) {
      renumber[v] = static_cast<Index>(kept.size());
      kept.push_back(hexes.points[v]);
    }
  s.unused_vertices = static_cast<Index>(hexes.points.size() - kept.size());
  hexes.points = std::move(kept);
  for (auto& cell : hexes.cells)
    for (Index& v : cell) v = renumber[v];
  hexes.cell_region.assign(hexes.cells.size(), kRegion);

  if (stats) *stats = s;
  return to_poly_mesh(hexes);
}

}  // namespace volmesh
