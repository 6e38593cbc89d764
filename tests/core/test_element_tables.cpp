// The reference cells' tables (element_mesh.hpp) agree with each other and with the corner
// order: every edge lies on two faces, faces point out, frames are positive.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/geometry.hpp"

namespace volmesh {
namespace {

const std::array<Vec3, 4> kUnitTet{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
const std::array<Vec3, 8> kUnitCube{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0},
                                    Vec3{0, 0, 1}, Vec3{1, 0, 1}, Vec3{1, 1, 1}, Vec3{0, 1, 1}};

// The edges of the face loops, each as (smaller corner, larger), with how often they appear.
template <std::size_t N, std::size_t F>
std::map<std::pair<int, int>, int> loop_edges(const std::array<std::array<int, F>, N>& faces) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& f : faces)
    for (std::size_t k = 0; k < F; ++k) {
      const int a = f[k], b = f[(k + 1) % F];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  return uses;
}

template <std::size_t N>
std::set<std::pair<int, int>> edge_set(const std::array<std::array<int, 2>, N>& edges) {
  std::set<std::pair<int, int>> out;
  for (const auto& [a, b] : edges) out.insert({std::min(a, b), std::max(a, b)});
  return out;
}

TEST(ElementTables, EveryEdgeLiesOnTwoFacesAndNoOtherPairDoes) {
  const auto tet = loop_edges(kTetFaces);
  EXPECT_EQ(tet.size(), kTetEdges.size());
  for (const auto& [edge, uses] : tet) {
    EXPECT_EQ(uses, 2);
    EXPECT_TRUE(edge_set(kTetEdges).count(edge));
  }
  const auto hex = loop_edges(kHexFaces);
  EXPECT_EQ(hex.size(), kHexEdges.size());
  for (const auto& [edge, uses] : hex) {
    EXPECT_EQ(uses, 2);
    EXPECT_TRUE(edge_set(kHexEdges).count(edge));
  }
}

// Each face with the cell's centroid behind it makes a positive tet.
TEST(ElementTables, FacesPointOutOfTheUnitCells) {
  const Vec3 tet_centre = (kUnitTet[0] + kUnitTet[1] + kUnitTet[2] + kUnitTet[3]) / 4.0;
  for (const auto& f : kTetFaces)
    EXPECT_GT(tet_volume(kUnitTet[f[0]], kUnitTet[f[2]], kUnitTet[f[1]], tet_centre), 0.0);
  const Vec3 cube_centre(0.5, 0.5, 0.5);
  for (const auto& f : kHexFaces)
    for (int k = 1; k + 1 < 4; ++k)
      EXPECT_GT(tet_volume(kUnitCube[f[0]], kUnitCube[f[k + 1]], kUnitCube[f[k]], cube_centre),
                0.0);
}

TEST(ElementTables, OppositeTetEdgesShareNoCorner) {
  std::set<int> seen;
  for (std::size_t e = 0; e < kTetEdges.size(); ++e) {
    const auto& [a, b] = kTetEdges[e];
    const auto& [c, d] = kTetEdges[kTetOppositeEdges[e]];
    EXPECT_EQ(std::set<int>({a, b, c, d}).size(), 4u) << "edge " << e;
    EXPECT_EQ(kTetOppositeEdges[kTetOppositeEdges[e]], static_cast<int>(e));
    seen.insert(kTetOppositeEdges[e]);
  }
  EXPECT_EQ(seen.size(), kTetEdges.size());
}

TEST(ElementTables, HexCornerFramesAreEdgesAndPositive) {
  const auto edges = edge_set(kHexEdges);
  for (int k = 0; k < 8; ++k) {
    const auto& [corner, a, b, c] = kHexCornerFrames[k];
    EXPECT_EQ(corner, k);
    for (const int n : {a, b, c})
      EXPECT_TRUE(edges.count({std::min(corner, n), std::max(corner, n)}));
    EXPECT_NEAR(tet_volume(kUnitCube[corner], kUnitCube[a], kUnitCube[b], kUnitCube[c]),
                1.0 / 6.0, 1e-15);
  }
}

}  // namespace
}  // namespace volmesh
