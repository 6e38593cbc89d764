// A rank's piece of the grid: the hexahedra of its stretch of the level's Morton curve, built
// as structured_hex_mesh builds them (the same points to the bit, the same corner order and
// boundary quads), the faces towards other ranks' cells tagged procBoundary.
#include "volmesh/octree_dist/grid_piece.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/element_mesh.hpp"
#include "volmesh/octree/octree.hpp"
#include "volmesh/partition/part_mesh.hpp"

namespace volmesh {
namespace {

// Per kHexFaces face of a cell: the step to the neighbour across it, and the box side it lies
// on at the grid's edge (structured_hex_mesh's tags: xmin xmax ymin ymax zmin zmax).
constexpr std::array<std::array<int, 3>, 6> kFaceStep{
    {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}}};
constexpr std::array<int, 6> kFaceSide{4, 5, 2, 1, 3, 0};
constexpr int kBoxSides = 6;

using Cell = std::array<std::int64_t, 3>;

// The ranks' stretches of the curve: rank r holds codes [first[r], first[r + 1]).
struct Stretches {
  std::vector<std::int64_t> first;
  int rank_of(std::int64_t code) const {
    return static_cast<int>(std::upper_bound(first.begin(), first.end(), code) - first.begin()) - 1;
  }
};

Stretches stretches(std::int64_t cells, int ranks) {
  Stretches s;
  for (int r = 0; r <= ranks; ++r) s.first.push_back(cells * r / ranks);
  return s;
}

std::uint64_t code_of(const Cell& c) {
  return morton_encode({static_cast<std::uint32_t>(c[0]), static_cast<std::uint32_t>(c[1]),
                        static_cast<std::uint32_t>(c[2])});
}

}  // namespace

RankPiece grid_piece(const Box3& box, int level) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const std::int64_t n = std::int64_t{1} << level;
  const Stretches curve = stretches(n * n * n, ranks);
  const auto inside = [n](const Cell& c) {
    return std::all_of(c.begin(), c.end(), [n](std::int64_t x) { return x >= 0 && x < n; });
  };

  // The cells' corners as Morton keys of grid points, sorted: the piece's points in order.
  std::vector<Cell> cells;
  std::vector<std::uint64_t> keys;
  for (std::int64_t code = curve.first[rank]; code < curve.first[rank + 1]; ++code) {
    const GridPoint g = morton_decode(static_cast<std::uint64_t>(code));
    const Cell& c = cells.emplace_back(Cell{g[0], g[1], g[2]});
    for (int k = 0; k < 8; ++k)
      keys.push_back(code_of({c[0] + (k & 1), c[1] + (k >> 1 & 1), c[2] + (k >> 2 & 1)}));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  const auto point = [&keys](const Cell& p) {
    return static_cast<Index>(std::lower_bound(keys.begin(), keys.end(), code_of(p)) - keys.begin());
  };

  HexMesh hex;
  RankPiece out;
  for (const std::uint64_t key : keys) {
    const GridPoint g = morton_decode(key);
    const Vec3 t(double(g[0]) / n, double(g[1]) / n, double(g[2]) / n);
    hex.points.push_back(box.lo + (box.hi - box.lo).cwiseProduct(t));
    // The lowest rank among the cells around the point.
    int owner = ranks;
    for (int k = 0; k < 8; ++k) {
      const Cell around{std::int64_t(g[0]) - (k & 1), std::int64_t(g[1]) - (k >> 1 & 1),
                        std::int64_t(g[2]) - (k >> 2 & 1)};
      if (inside(around)) owner = std::min(owner, curve.rank_of(code_of(around)));
    }
    out.point_owner.push_back(owner);
  }
  hex.tag_names = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  std::vector<int> neighbour_ranks;  // per face towards another rank, that rank
  std::vector<std::array<Index, 4>> rank_faces;
  for (const Cell& c : cells) {
    const auto& h = hex.cells.emplace_back(std::array<Index, 8>{
        point(c), point({c[0] + 1, c[1], c[2]}), point({c[0] + 1, c[1] + 1, c[2]}),
        point({c[0], c[1] + 1, c[2]}), point({c[0], c[1], c[2] + 1}),
        point({c[0] + 1, c[1], c[2] + 1}), point({c[0] + 1, c[1] + 1, c[2] + 1}),
        point({c[0], c[1] + 1, c[2] + 1})});
    out.global_cells.push_back(c[0] + n * (c[1] + n * c[2]));
    for (int f = 0; f < 6; ++f) {
      const Cell next{c[0] + kFaceStep[f][0], c[1] + kFaceStep[f][1], c[2] + kFaceStep[f][2]};
      const std::array<Index, 4> quad{h[kHexFaces[f][0]], h[kHexFaces[f][1]], h[kHexFaces[f][2]],
                                      h[kHexFaces[f][3]]};
      if (!inside(next)) {
        hex.boundary_faces.push_back(quad);
        hex.boundary_tag.push_back(kFaceSide[f]);
      } else if (const int other = curve.rank_of(code_of(next)); other != rank) {
        rank_faces.push_back(quad);
        neighbour_ranks.push_back(other);
      }
    }
  }
  // The faces towards each other rank under one tag, the ranks in increasing order.
  std::vector<int> others = neighbour_ranks;
  std::sort(others.begin(), others.end());
  others.erase(std::unique(others.begin(), others.end()), others.end());
  for (const int other : others) hex.tag_names.push_back(part_boundary_name(rank, other));
  for (std::size_t f = 0; f < rank_faces.size(); ++f) {
    hex.boundary_faces.push_back(rank_faces[f]);
    hex.boundary_tag.push_back(
        kBoxSides + static_cast<Index>(std::lower_bound(others.begin(), others.end(), neighbour_ranks[f]) - others.begin()));
  }
  hex.cell_region.assign(hex.cells.size(), 1);
  out.mesh = to_poly_mesh(hex);

  for (const std::uint64_t key : keys) {
    const GridPoint g = morton_decode(key);
    out.global_points.push_back(g[0] + (n + 1) * (g[1] + (n + 1) * g[2]));
  }
  out.global_point_count = (n + 1) * (n + 1) * (n + 1);
  out.global_cell_count = n * n * n;
  return out;
}

}  // namespace volmesh
