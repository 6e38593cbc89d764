// Triangulations of closed contour components: divide and conquer (Algorithm 1 of the
// octree paper), fans, and §4.1's construction across two or three faces.
#include <gtest/gtest.h>

#include <set>

#include "loop_triangulation.hpp"

namespace volmesh::cutcell {
namespace {

// The regular hexagon cut from the unit cube by the plane x + y + z = 1.5, its points on
// six edges, in order; bit k of faces marks cube face k (x-, x+, y-, y+, z-, z+).
struct Hexagon {
  std::vector<Vec3> position{{0.5, 0, 1}, {1, 0, 0.5}, {1, 0.5, 0}, {0.5, 1, 0}, {0, 1, 0.5}, {0, 0.5, 1}};
  std::vector<std::uint8_t> faces{0b100100, 0b000110, 0b010010, 0b011000, 0b001001, 0b100001};
  std::vector<int> loop{0, 1, 2, 3, 4, 5};
};

Vec3 vector_area(const std::vector<Vec3>& p, const std::vector<int>& loop) {
  Vec3 a = Vec3::Zero();
  for (std::size_t i = 0; i < loop.size(); ++i) a += 0.5 * p[loop[i]].cross(p[loop[(i + 1) % loop.size()]]);
  return a;
}

// Triangles cover the loop once, with its orientation: their area vectors add up to the
// loop's, each loop edge appears once in its direction, every inner edge twice (once each
// way), and no new edge joins two points on a common face.
void expect_triangulates(const std::vector<Vec3>& p, const std::vector<std::uint8_t>& faces,
                         const std::vector<int>& loop, const std::vector<Triangle>& t) {
  Vec3 area = Vec3::Zero();
  std::multiset<std::pair<int, int>> edges;
  for (const Triangle& tri : t) {
    area += 0.5 * (p[tri[1]] - p[tri[0]]).cross(p[tri[2]] - p[tri[0]]);
    for (int k = 0; k < 3; ++k) edges.insert({tri[k], tri[(k + 1) % 3]});
  }
  EXPECT_LT((area - vector_area(p, loop)).norm(), 1e-12);
  std::set<std::pair<int, int>> boundary;
  for (std::size_t i = 0; i < loop.size(); ++i) boundary.insert({loop[i], loop[(i + 1) % loop.size()]});
  for (const auto& e : edges) {
    if (boundary.count(e)) {
      EXPECT_EQ(edges.count(e), 1u);
      continue;
    }
    EXPECT_EQ(edges.count({e.second, e.first}), 1u) << e.first << "-" << e.second;
    if (e.first < static_cast<int>(faces.size()) && e.second < static_cast<int>(faces.size())) {
      EXPECT_EQ(faces[e.first] & faces[e.second], 0) << "diagonal on a face " << e.first << "-" << e.second;
    }
  }
}

TEST(LoopTriangulation, DivideAndConquerTriangulatesAHexagon) {
  const Hexagon h;
  const auto t = triangulate_divide_and_conquer({h.position, h.faces}, h.loop);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->size(), 4u);
  expect_triangulates(h.position, h.faces, h.loop, *t);
}

TEST(LoopTriangulation, DivideAndConquerOfANonPlanarLoop) {
  // A saddle-shaped loop over four faces of the unit cube (the octree paper's non-planar
  // sequences): points on the four vertical edges at alternating heights, with the four
  // mid-face points between them.
  std::vector<Vec3> p{{0, 0, 0.2}, {0.5, 0, 0.5}, {1, 0, 0.8}, {1, 0.5, 0.5}, {1, 1, 0.2},
                      {0.5, 1, 0.5}, {0, 1, 0.8}, {0, 0.5, 0.5}};
  std::vector<std::uint8_t> faces{0b000101, 0b000100, 0b000110, 0b000010, 0b001010, 0b001000, 0b001001, 0b000001};
  std::vector<int> loop{0, 1, 2, 3, 4, 5, 6, 7};
  const auto t = triangulate_divide_and_conquer({p, faces}, loop);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->size(), 6u);
  expect_triangulates(p, faces, loop, *t);
}

TEST(LoopTriangulation, DivideAndConquerAvoidsDiagonalsOnAFace) {
  // A quad whose diagonal 0-2 would lie in face 0: only 1-3 is allowed.
  std::vector<Vec3> p{{0, 0, 0}, {0.5, 0, 1}, {0, 1, 1}, {0.5, 1, 0}};
  std::vector<std::uint8_t> faces{0b01, 0b10, 0b01, 0b100};
  std::vector<int> loop{0, 1, 2, 3};
  const auto t = triangulate_divide_and_conquer({p, faces}, loop);
  ASSERT_TRUE(t.has_value());
  expect_triangulates(p, faces, loop, *t);
  // With both diagonals on faces there is none.
  std::vector<std::uint8_t> blocked{0b01, 0b10, 0b11, 0b11};
  EXPECT_FALSE(triangulate_divide_and_conquer({p, blocked}, loop).has_value());
}

TEST(LoopTriangulation, DivideAndConquerOfALoopWithAReflexPoint) {
  // A pentagon notched at D = (2, 1): no diagonal has the other points on its two sides
  // (A-D has B and C apart, B-D has A and E apart), as on a face the vertex moves warped
  // nearly along an interface (builtin:layers6 at level 6). The diagonals inside the loop
  // are taken then, and no triangle folds.
  std::vector<Vec3> p{{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {2, 1, 0}, {0, 3, 0}};
  std::vector<std::uint8_t> faces(5, 0);
  std::vector<int> loop{0, 1, 2, 3, 4};
  const auto t = triangulate_divide_and_conquer({p, faces}, loop);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->size(), 3u);
  expect_triangulates(p, faces, loop, *t);
  for (const Triangle& tri : *t)
    EXPECT_GT((p[tri[1]] - p[tri[0]]).cross(p[tri[2]] - p[tri[0]]).z(), 0.0) << tri[0] << tri[1] << tri[2];
}

TEST(LoopTriangulation, FanAroundAnInnerPointOrAPointOfTheLoop) {
  Hexagon h;
  h.position.push_back(Vec3::Constant(0.5));
  h.faces.push_back(0);
  const std::vector<Triangle> inner = triangulate_fan(h.loop, 6);
  EXPECT_EQ(inner.size(), 6u);
  expect_triangulates(h.position, h.faces, h.loop, inner);
  // Around a point of the loop itself (the cell interface point), the two edges at it are
  // left out.
  std::vector<int> through{0, 1, 2, 3, 4, 5, 6};
  const std::vector<Triangle> on = triangulate_fan(through, 6);
  EXPECT_EQ(on.size(), 5u);
  expect_triangulates(h.position, h.faces, through, on);
}

TEST(LoopTriangulation, AcrossThreeFacesAroundACorner) {
  // A loop over faces x+ (bit 1), y+ (bit 3) and z+ (bit 5) around corner (1, 1, 1), with
  // inner points on each face: chains A1..An, B1..Bm, C1..Ck of §4.1.
  std::vector<Vec3> p{{1, 0.2, 1},   {1, 0.4, 0.6}, {1, 1, 0.3}, {0.5, 1, 0.5},
                      {0.2, 1, 1},   {0.5, 0.5, 1}};
  std::vector<std::uint8_t> faces{0b100010, 0b000010, 0b001010, 0b001000, 0b101000, 0b100000};
  std::vector<int> loop{0, 1, 2, 3, 4, 5};
  const auto t = triangulate_across_faces({p, faces}, loop);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->size(), 4u);
  expect_triangulates(p, faces, loop, *t);
}

TEST(LoopTriangulation, AcrossFacesRefusesOtherLoops) {
  const Hexagon h;  // over all six faces
  EXPECT_FALSE(triangulate_across_faces({h.position, h.faces}, h.loop).has_value());
}

}  // namespace
}  // namespace volmesh::cutcell
