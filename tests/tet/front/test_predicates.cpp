// The front's rejection tests (predicates.hpp) where a front triangle shares corners with the
// candidate tet: exact in both directions (a front edge exactly in a tet face's plane and
// over it meets the tet, one off the plane by a rounding does not), the separation filters
// never hiding a crossing, and the flat-gap rule refusing what lies over a face up to 1e-6.
#include <gtest/gtest.h>

#include "predicates.hpp"

namespace volmesh::tet::front {
namespace {

// The unit corner tet, positive; its corners are nodes 0 to 3.
const std::array<Corner, 4> kTet{Corner{Vec3(0, 0, 0), 0}, Corner{Vec3(1, 0, 0), 1},
                                 Corner{Vec3(0, 1, 0), 2}, Corner{Vec3(0, 0, 1), 3}};

std::array<Corner, 3> triangle(const Corner& a, const Vec3& b, const Vec3& c) {
  return {a, Corner{b, 10}, Corner{c, 11}};
}

TEST(FrontPredicates, AFaceOfTheTetMeetsItOnlyThere) {
  EXPECT_FALSE(tet_meets_triangle(kTet, {kTet[0], kTet[2], kTet[1]}));
  EXPECT_FALSE(leaves_flat_gap(kTet, {kTet[0], kTet[2], kTet[1]}));
}

TEST(FrontPredicates, ATriangleAtACornerMeetsTheTetOnlyWhenItEntersIt) {
  // Into the tet from corner 0, and away from it behind the face x = 0.
  EXPECT_TRUE(tet_meets_triangle(kTet, triangle(kTet[0], Vec3(0.2, 0.2, 0.2), Vec3(0.3, 0.1, 0.1))));
  EXPECT_FALSE(tet_meets_triangle(kTet, triangle(kTet[0], Vec3(-1, 0.5, 0.5), Vec3(-1, -0.5, 0.5))));
  // From corner 1 through the tet and out of its face x = 0, its other corners outside: the
  // filters must not take it for separated.
  EXPECT_TRUE(tet_meets_triangle(kTet, triangle(kTet[1], Vec3(-1, 0.3, 0.3), Vec3(-1, 0.2, 0.1))));
}

TEST(FrontPredicates, ATriangleOnAnEdgeMeetsTheTetOnlyWhenItEntersIt) {
  // On edge 0-1: leaning into the tet, and folded away below the face z = 0.
  EXPECT_TRUE(tet_meets_triangle(kTet, {kTet[0], kTet[1], Corner{Vec3(0.2, 0.3, 0.3), 10}}));
  EXPECT_FALSE(tet_meets_triangle(kTet, {kTet[0], kTet[1], Corner{Vec3(0.2, 0.3, -0.3), 10}}));
  // In the plane z = 0 beyond the tet's face there: meets only along the shared edge.
  EXPECT_FALSE(tet_meets_triangle(kTet, {kTet[1], kTet[0], Corner{Vec3(0.5, -0.5, 0), 10}}));
  // In the plane z = 0 over the tet's face: overlaps it.
  EXPECT_TRUE(tet_meets_triangle(kTet, {kTet[0], kTet[1], Corner{Vec3(0.3, 0.3, 0), 10}}));
}

TEST(FrontPredicates, AnEdgeInAFacesPlaneIsDecidedExactly) {
  // An edge from corner 0 exactly in the plane z = 0, over the tet's face there: it meets.
  const Vec3 over(0.2, 0.2, 0.0), beyond(-0.2, 0.2, 0.0);
  EXPECT_TRUE(tet_meets_triangle(kTet, triangle(kTet[0], over, Vec3(0.2, 0.2, -1))));
  // In the plane but outside the face's wedge at corner 0: it does not.
  EXPECT_FALSE(tet_meets_triangle(kTet, triangle(kTet[0], beyond, Vec3(-0.2, 0.2, -1))));
  // Below the plane by a rounding: exactly outside the tet, but a gap no tet could fill.
  const Vec3 below(0.2, 0.2, -1e-12);
  const auto thin = triangle(kTet[0], below, Vec3(0.2, 0.2, -1));
  EXPECT_FALSE(tet_meets_triangle(kTet, thin));
  EXPECT_TRUE(leaves_flat_gap(kTet, thin));
  // Well below it: neither.
  const auto clear = triangle(kTet[0], Vec3(0.2, 0.2, -0.1), Vec3(0.2, 0.2, -1));
  EXPECT_FALSE(tet_meets_triangle(kTet, clear));
  EXPECT_FALSE(leaves_flat_gap(kTet, clear));
}

}  // namespace
}  // namespace volmesh::tet::front
