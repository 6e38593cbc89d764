// The face-adjacency graph: degrees on a structured grid, hanging faces, faces shared twice
// by the same cells, refusals, and connected pieces.
#include <gtest/gtest.h>

#include <map>

#include "../support/unit_cube_meshes.hpp"
#include "partition_test_support.hpp"
#include "volmesh/core/errors.hpp"
#include "volmesh/partition/dual_graph.hpp"

namespace volmesh::test {
namespace {

// Symmetric, sorted, without self-loops, and the weights count each internal face once.
void expect_well_formed(const PolyMesh& mesh, const DualGraph& graph) {
  ASSERT_EQ(graph.num_vertices(), mesh.num_cells());
  std::map<std::pair<Index, Index>, Index> weight;
  for (Index c = 0; c < graph.num_vertices(); ++c) {
    const auto others = graph.neighbours(c);
    EXPECT_TRUE(std::is_sorted(others.begin(), others.end()));
    EXPECT_EQ(std::adjacent_find(others.begin(), others.end()), others.end()) << "cell " << c;
    for (std::size_t k = 0; k < others.size(); ++k) {
      EXPECT_NE(others[k], c);
      weight[{c, others[k]}] = graph.weights(c)[k];
    }
  }
  Index internal_faces = 0, total_weight = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) internal_faces += mesh.is_boundary(f) ? 0 : 1;
  for (const auto& [edge, w] : weight) {
    EXPECT_EQ((weight.count({edge.second, edge.first})), 1u);
    EXPECT_EQ((weight[{edge.second, edge.first}]), w);
    total_weight += w;
  }
  EXPECT_EQ(total_weight, 2 * internal_faces);
}

TEST(DualGraph, StructuredHexDegrees) {
  const Index n[3] = {3, 4, 5};
  const PolyMesh mesh = hex_grid(n[0], n[1], n[2]);
  const DualGraph graph = build_dual_graph(mesh);
  expect_well_formed(mesh, graph);
  // A cell has one neighbour per axis direction that does not leave the grid.
  std::map<Index, Index> expected, actual;
  for (Index i = 0; i < n[0]; ++i)
    for (Index j = 0; j < n[1]; ++j)
      for (Index k = 0; k < n[2]; ++k) {
        Index degree = 0;
        for (auto [x, m] : {std::pair{i, n[0]}, std::pair{j, n[1]}, std::pair{k, n[2]}})
          degree += (x > 0) + (x < m - 1);
        ++expected[degree];
      }
  for (Index c = 0; c < graph.num_vertices(); ++c) ++actual[graph.degree(c)];
  EXPECT_EQ(actual, expected);  // 8 corners of degree 3, ..., 6 inner cells of degree 6
  EXPECT_EQ(expected[3], 8);
  EXPECT_EQ(expected[6], 1 * 2 * 3);
  EXPECT_EQ(graph.num_edges(), 2 * 4 * 5 + 3 * 3 * 5 + 3 * 4 * 4);
  EXPECT_TRUE(
      std::all_of(graph.adjwgt.begin(), graph.adjwgt.end(), [](Index w) { return w == 1; }));
}

// The octree case METIS_PartMeshDual gets wrong: the big cube shares one face with each of
// the four small cubes on its side, and each small cube touches two of its siblings.
TEST(DualGraph, BigCubeHasOneEdgePerSmallNeighbour) {
  const PolyMesh mesh = big_cube_next_to_four_small();
  const DualGraph graph = build_dual_graph(mesh);
  expect_well_formed(mesh, graph);
  ASSERT_EQ(graph.degree(0), 4);
  EXPECT_EQ(std::vector<Index>(graph.neighbours(0).begin(), graph.neighbours(0).end()),
            (std::vector<Index>{1, 2, 3, 4}));
  for (Index c = 1; c <= 4; ++c) {
    EXPECT_EQ(graph.degree(c), 3) << "small cube " << c;
    EXPECT_EQ(graph.neighbours(c).front(), 0);
  }
  EXPECT_EQ(graph.num_edges(), 8);
}

// Two hexes whose shared side is stored as two triangles: one edge of weight 2.
TEST(DualGraph, FacesSharedTwiceMakeOneEdgeOfWeightTwo) {
  PolyMesh mesh = hex_grid(2, 1, 1);
  Index shared = kNoIndex;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (!mesh.is_boundary(f)) shared = f;
  ASSERT_NE(shared, kNoIndex);
  const std::vector<Index> quad(mesh.face(shared).begin(), mesh.face(shared).end());
  PolyMesh split;
  split.points = mesh.points;
  split.tag_names = mesh.tag_names;
  split.cell_region = mesh.cell_region;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (f != shared) {
      split.add_face(mesh.face(f), mesh.owner[f], mesh.neighbour[f], mesh.face_tag[f]);
      continue;
    }
    split.add_face(std::vector<Index>{quad[0], quad[1], quad[2]}, mesh.owner[f], mesh.neighbour[f]);
    split.add_face(std::vector<Index>{quad[0], quad[2], quad[3]}, mesh.owner[f], mesh.neighbour[f]);
  }
  const DualGraph graph = build_dual_graph(split);
  expect_well_formed(split, graph);
  EXPECT_EQ(graph.adjncy, (std::vector<Index>{1, 0}));
  EXPECT_EQ(graph.adjwgt, (std::vector<Index>{2, 2}));
}

TEST(DualGraph, BadFacesAreRefusedByName) {
  PolyMesh mesh = hex_grid(2, 1, 1);
  Index shared = kNoIndex;
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (!mesh.is_boundary(f)) shared = f;
  mesh.neighbour[shared] = mesh.owner[shared];
  try {
    build_dual_graph(mesh, "two.vtu");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "two.vtu: face " + std::to_string(shared) + ": cell " +
                                         std::to_string(mesh.owner[shared]) + " on both sides");
  }
  mesh.neighbour[shared] = 7;
  EXPECT_THROW(build_dual_graph(mesh, "two.vtu"), InputError);
}

TEST(DualGraph, ComponentsOfParts) {
  const DualGraph graph = build_dual_graph(hex_grid(4, 1, 1));  // a row of 4 cells
  EXPECT_EQ(part_components(graph, std::vector<Index>{0, 0, 0, 0}, 1), std::vector<Index>{1});
  EXPECT_EQ(part_components(graph, std::vector<Index>{0, 0, 1, 1}, 2), (std::vector<Index>{1, 1}));
  EXPECT_EQ(part_components(graph, std::vector<Index>{0, 1, 0, 1}, 3),
            (std::vector<Index>{2, 2, 0}));
}

}  // namespace
}  // namespace volmesh::test
