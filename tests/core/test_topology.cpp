#include <gtest/gtest.h>

#include "../support/unit_cube_meshes.hpp"
#include "volmesh/core/convert.hpp"
#include "volmesh/core/structured.hpp"
#include "volmesh/core/topology.hpp"

namespace volmesh {
namespace {

TEST(Topology, EdgesOfAHexGridFollowEulersCount) {
  // An n^3 grid has 3 n (n+1)^2 edges.
  const PolyMesh p = to_poly_mesh(structured_hex_mesh(Vec3::Zero(), Vec3::Ones(), {3, 3, 3}));
  const MeshEdges e = build_edges(p);
  EXPECT_EQ(e.edges.size(), 3u * 3 * 16);
  for (Index f = 0; f < p.num_faces(); ++f) {
    const auto loop = p.face(f);
    const auto edges = e.of_face(f);
    ASSERT_EQ(edges.size(), loop.size());
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const auto [a, b] = e.edges[edges[k]];
      const Index u = loop[k], v = loop[(k + 1) % loop.size()];
      EXPECT_EQ(a, std::min(u, v));
      EXPECT_EQ(b, std::max(u, v));
    }
  }
}

TEST(Topology, HangingNodeMeshEdgesAndPointCells) {
  const PolyMesh p = test::big_cube_next_to_four_small();
  const MeshEdges e = build_edges(p);
  // V - E + F - C = 1 for a 3-ball: 8 + 18 + 9 - 4 (shared) = 31 points.
  const Index faces = p.num_faces(), cells = p.num_cells();
  EXPECT_EQ(p.num_points() - static_cast<Index>(e.edges.size()) + faces - cells, 1);
  const PointCells pc = build_point_cells(p);
  // The hanging node in the middle of the big cube's +x side touches all five cells.
  for (Index v = 0; v < p.num_points(); ++v)
    if (p.points[v] == Vec3(1, 0.5, 0.5)) {
      EXPECT_EQ(pc.of(v).size(), 5u);
    }
  EXPECT_EQ(pc.of(0).size(), 1u);  // (0,0,0): the big cube only
}

}  // namespace
}  // namespace volmesh
