#include "volmesh/hexdc/dual_contouring.hpp"

#include <algorithm>
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
  std::vector<char> used(hexes.points.size(), 0);
  for (Index k = 0; k + 1 < n; ++k)
    for (Index j = 0; j + 1 < n; ++j)
      for (Index i = 0; i + 1 < n; ++i) {
        std::array<Index, 8> cell{};
        std::array<Vec3, 8> corners;
        bool complete = true;
        for (std::size_t c = 0; c < 8 && complete; ++c) {
          const auto& o = kCornerOffset[c];
          cell[c] = vertex[node_id(i + o[0], j + o[1], k + o[2])];
          complete = cell[c] != kNoIndex;
          if (complete) corners[c] = hexes.points[cell[c]];
        }
        if (!complete) continue;
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
