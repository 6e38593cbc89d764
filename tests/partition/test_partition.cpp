// METIS partitions: one part without METIS, refusals, non-empty and balanced parts,
// determinism, statistics checked against the faces, contiguity, weights, and the parts as
// meshes of their own.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <set>

#include "../support/unit_cube_meshes.hpp"
#include "partition_test_support.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/core/validity.hpp"
#include "volmesh/partition/part_mesh.hpp"
#include "volmesh/partition/partition.hpp"

namespace volmesh::test {
namespace {

PartitionOptions parts(Index k, PartitionMethod method = PartitionMethod::KWay) {
  PartitionOptions options;
  options.parts = k;
  options.method = method;
  return options;
}

std::string error_of(const PolyMesh& mesh, const PartitionOptions& options) {
  try {
    partition_mesh(mesh, options, "m.vtu");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// Edge cut, interface faces and part sizes recounted from the mesh's faces.
void expect_stats_match_faces(const PolyMesh& mesh, const Partition& p) {
  const PartitionStats& s = p.stats;
  Index cut = 0;
  std::vector<Index> interface_faces(s.parts, 0), cells(s.parts, 0);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.is_boundary(f)) continue;
    const Index a = p.cell_part[mesh.owner[f]], b = p.cell_part[mesh.neighbour[f]];
    if (a == b) continue;
    ++cut;
    ++interface_faces[a];
    ++interface_faces[b];
  }
  for (Index part : p.cell_part) ++cells[part];
  EXPECT_EQ(s.edge_cut, cut);
  EXPECT_EQ(s.part_interface_faces, interface_faces);
  EXPECT_EQ(s.part_cells, cells);
  const Index largest = *std::max_element(cells.begin(), cells.end());
  EXPECT_DOUBLE_EQ(s.imbalance, static_cast<double>(largest) * s.parts / mesh.num_cells());
}

TEST(Partition, OnePartDoesNotCallMetis) {
  // A single cell: METIS 5.1 fails or crashes on such input; one part never reaches it.
  const PolyMesh one = to_poly_mesh(unit_cube_hex());
  const Partition p = partition_mesh(one, parts(1));
  EXPECT_EQ(p.cell_part, std::vector<Index>{0});
  EXPECT_EQ(p.stats.method, "none");
  EXPECT_EQ(p.stats.edge_cut, 0);
  EXPECT_EQ(p.stats.imbalance, 1.0);
  const Partition q = partition_mesh(hex_grid(3, 3, 3), parts(1));
  EXPECT_EQ(q.cell_part, std::vector<Index>(27, 0));
  EXPECT_EQ(q.stats.part_interface_faces, std::vector<Index>{0});
}

TEST(Partition, ImpossiblePartCountsAreRefused) {
  const PolyMesh mesh = big_cube_next_to_four_small();
  EXPECT_EQ(error_of(mesh, parts(6)), "m.vtu: cannot split 5 cells into 6 non-empty parts");
  EXPECT_EQ(error_of(mesh, parts(0)), "m.vtu: cannot make 0 parts (at least 1)");
  PartitionOptions weighted = parts(2);
  weighted.cell_weights = {1, 1, 1};
  EXPECT_EQ(error_of(mesh, weighted), "m.vtu: 3 cell weights for 5 cells");
  weighted.cell_weights = {1, 1, -2, 1, 1};
  EXPECT_EQ(error_of(mesh, weighted), "m.vtu: cell 2: weight -2 (weights are >= 0)");
}

// METIS leaves parts empty when K nears the cell count; every part still gets a cell.
TEST(Partition, EveryPartIsNonEmptyUpToOneCellEach) {
  for (const PolyMesh& mesh : {big_cube_next_to_four_small(), hex_grid(3, 3, 3)})
    for (PartitionMethod method : {PartitionMethod::KWay, PartitionMethod::Recursive})
      for (Index k = 2; k <= mesh.num_cells(); ++k) {
        const Partition p = partition_mesh(mesh, parts(k, method));
        ASSERT_EQ(p.cell_part.size(), static_cast<std::size_t>(mesh.num_cells()));
        for (Index part : p.cell_part) ASSERT_TRUE(part >= 0 && part < k);
        EXPECT_EQ(std::count(p.stats.part_cells.begin(), p.stats.part_cells.end(), 0), 0)
            << k << " parts of " << mesh.num_cells() << " cells";
        expect_stats_match_faces(mesh, p);
      }
}

// The balance users accept, on 46^3 = 97,336 hexes: imbalance <= 1.03 for K = 2 .. 64.
TEST(Partition, BalancedOnAHundredThousandCells) {
  const PolyMesh mesh = hex_grid(46, 46, 46);
  const DualGraph graph = build_dual_graph(mesh);
  for (Index k : {2, 3, 4, 5, 7, 8, 13, 16, 27, 32, 50, 63, 64}) {
    const Partition p = partition_graph(graph, parts(k));
    EXPECT_LE(p.stats.imbalance, 1.03) << k << " parts";
    EXPECT_EQ(p.stats.filled_empty_parts, 0) << k << " parts";
    EXPECT_TRUE(p.stats.all_contiguous()) << k << " parts";
    // k cubes of N/k cells have k * 6 (N/k)^(2/3) / 2 faces between them at most: the cut
    // stays below twice that.
    const double cube_faces = 6 * std::pow(mesh.num_cells() / double(k), 2.0 / 3.0);
    EXPECT_LT(p.stats.edge_cut, k * cube_faces) << k << " parts";
  }
}

TEST(Partition, SameInputSameParts) {
  const PolyMesh mesh = hex_grid(20, 17, 9);
  for (PartitionMethod method : {PartitionMethod::KWay, PartitionMethod::Recursive}) {
    const Partition a = partition_mesh(mesh, parts(7, method));
    const Partition b = partition_mesh(mesh, parts(7, method));
    EXPECT_EQ(a.cell_part, b.cell_part);
    EXPECT_EQ(a.stats.method, method == PartitionMethod::KWay ? "kway" : "recursive");
    expect_stats_match_faces(mesh, a);
  }
}

TEST(Partition, NeighbourCountsAreSymmetric) {
  const PolyMesh mesh = hex_grid(12, 12, 12);
  const Partition p = partition_mesh(mesh, parts(9));
  std::set<std::pair<Index, Index>> touching;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (!mesh.is_boundary(f) && p.cell_part[mesh.owner[f]] != p.cell_part[mesh.neighbour[f]]) {
      touching.insert({p.cell_part[mesh.owner[f]], p.cell_part[mesh.neighbour[f]]});
      touching.insert({p.cell_part[mesh.neighbour[f]], p.cell_part[mesh.owner[f]]});
    }
  for (Index part = 0; part < 9; ++part)
    EXPECT_EQ(p.stats.part_neighbours[part],
              std::count_if(touching.begin(), touching.end(),
                            [&](const auto& t) { return t.first == part; }));
}

TEST(Partition, ContiguousPartsWhenTheMeshIsConnected) {
  const PolyMesh mesh = hex_grid(30, 30, 1);
  PartitionOptions options = parts(12);
  options.contiguous = true;
  const Partition p = partition_mesh(mesh, options);
  EXPECT_TRUE(p.stats.contiguity_enforced);
  EXPECT_EQ(p.stats.mesh_components, 1);
  EXPECT_TRUE(p.stats.all_contiguous());
  EXPECT_EQ(p.stats.method, "kway");
}

// Two separate blocks cannot be cut into connected parts by METIS_OPTION_CONTIG: the mesh is
// partitioned without it, and the statistics say so.
TEST(Partition, DisconnectedMeshFallsBackWithoutContiguity) {
  PolyMesh mesh = hex_grid(4, 4, 4);
  const PolyMesh other = hex_grid(4, 4, 4);
  const Index offset_points = mesh.num_points(), offset_cells = mesh.num_cells();
  for (const Vec3& x : other.points) mesh.points.push_back(x + Vec3(2, 0, 0));
  for (Index f = 0; f < other.num_faces(); ++f) {
    std::vector<Index> loop;
    for (Index v : other.face(f)) loop.push_back(v + offset_points);
    mesh.add_face(loop, other.owner[f] + offset_cells,
                  other.is_boundary(f) ? kNoIndex : other.neighbour[f] + offset_cells,
                  other.face_tag[f]);
  }
  mesh.cell_region.insert(mesh.cell_region.end(), other.cell_region.begin(),
                          other.cell_region.end());
  ASSERT_TRUE(check_validity(mesh).valid());
  PartitionOptions options = parts(3);
  options.contiguous = true;
  const Partition p = partition_mesh(mesh, options);
  EXPECT_EQ(p.stats.mesh_components, 2);
  EXPECT_FALSE(p.stats.contiguity_enforced);
  EXPECT_EQ(std::count(p.stats.part_cells.begin(), p.stats.part_cells.end(), 0), 0);
}

// Cells that share no face give METIS a graph without edges.
TEST(Partition, CellsWithoutNeighbours) {
  PolyMesh mesh = to_poly_mesh(unit_cube_hex());
  const PolyMesh other = mesh;
  for (const Vec3& x : other.points) mesh.points.push_back(x + Vec3(3, 0, 0));
  for (Index f = 0; f < other.num_faces(); ++f) {
    std::vector<Index> loop;
    for (Index v : other.face(f)) loop.push_back(v + 8);
    mesh.add_face(loop, 1, kNoIndex, other.face_tag[f]);
  }
  mesh.cell_region.push_back(1);
  PartitionOptions options = parts(2);
  options.contiguous = true;
  const Partition p = partition_mesh(mesh, options);
  EXPECT_EQ(p.stats.part_cells, (std::vector<Index>{1, 1}));
  EXPECT_EQ(p.stats.edge_cut, 0);
  EXPECT_EQ(p.stats.mesh_components, 2);
}

TEST(Partition, WeightedCellsBalanceByWeight) {
  const PolyMesh mesh = hex_grid(16, 16, 16);
  PartitionOptions options = parts(4);
  options.cell_weights.assign(mesh.num_cells(), 1);
  // The cells of the lower half in z weigh 3: parts there have fewer cells.
  const CellFaces cf = build_cell_faces(mesh);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    double z = 0;
    for (Index f : cf.of(c))
      for (Index v : mesh.face(f)) z += mesh.points[v].z();
    if (z / 24 < 0.5) options.cell_weights[c] = 3;
  }
  const Partition p = partition_mesh(mesh, options);
  const std::int64_t total =
      std::accumulate(options.cell_weights.begin(), options.cell_weights.end(), std::int64_t{0});
  EXPECT_EQ(
      std::accumulate(p.stats.part_weights.begin(), p.stats.part_weights.end(), std::int64_t{0}),
      total);
  EXPECT_LE(p.stats.imbalance, 1.03);
  const auto [fewest, most] =
      std::minmax_element(p.stats.part_cells.begin(), p.stats.part_cells.end());
  EXPECT_GT(*most, *fewest * 3 / 2);  // unweighted counts are far from equal
}

// Each part as its own mesh: valid, the volumes add up, the faces towards other parts are
// tagged with the neighbour's number, the global ids lead back to the same cells and points,
// and the cells keep their global order.
TEST(Partition, PartsAsMeshes) {
  for (const PolyMesh& mesh : {big_cube_next_to_four_small(true), hex_grid(6, 5, 4)}) {
    const Index k = mesh.num_cells() == 5 ? 3 : 4;
    const Partition p = partition_mesh(mesh, parts(k));
    const std::vector<PartMesh> pieces = split_mesh(mesh, p.cell_part, k);
    ASSERT_EQ(pieces.size(), static_cast<std::size_t>(k));
    double volume = 0.0;
    Index cells = 0;
    for (Index part = 0; part < k; ++part) {
      const PartMesh& piece = pieces[part];
      const ValidityReport report = check_validity(piece.mesh);
      EXPECT_TRUE(report.valid()) << (report.problems.empty() ? "" : report.problems.front());
      volume += report.total_volume;
      cells += piece.mesh.num_cells();
      for (Index c = 0; c < piece.mesh.num_cells(); ++c) {
        EXPECT_EQ(p.cell_part[piece.global_cells[c]], part);
        EXPECT_EQ(piece.mesh.cell_region[c], mesh.cell_region[piece.global_cells[c]]);
      }
      EXPECT_TRUE(std::is_sorted(piece.global_cells.begin(), piece.global_cells.end()));
      for (Index v = 0; v < piece.mesh.num_points(); ++v)
        EXPECT_EQ(piece.mesh.points[v], mesh.points[piece.global_points[v]]);
      Index towards_others = 0;
      for (Index f = 0; f < piece.mesh.num_faces(); ++f)
        if (piece.mesh.is_boundary(f) &&
            piece.mesh.tag_names[piece.mesh.face_tag[f]].starts_with("procBoundary"))
          ++towards_others;
      EXPECT_EQ(towards_others, p.stats.part_interface_faces[part]);
    }
    EXPECT_EQ(cells, mesh.num_cells());
    EXPECT_NEAR(volume, check_validity(mesh).total_volume, 1e-12);
  }
}

}  // namespace
}  // namespace volmesh::test
