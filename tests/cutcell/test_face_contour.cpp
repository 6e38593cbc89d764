// M3S on single square faces: marching squares with the normal-based ambiguity rule, the
// diagonal rule, face interface points and their fallbacks, CMS feature points.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <cmath>

#include "face_contour.hpp"
#include "volmesh/core/geometry.hpp"

namespace volmesh::cutcell {
namespace {

// The unit square in z = 0, counter-clockwise about +z; corner k at (k == 1 || k == 2, k >= 2).
struct Square {
  std::array<Index, 4> region;
  // Interface point on side k (corner k -> k + 1), with its normal from corner k's region
  // into corner k + 1's; side k unset when the regions agree.
  std::array<std::optional<std::pair<Vec3, Vec3>>, 4> side;
  std::array<bool, 4> midpoint{};  // a hanging vertex halfway along side k (corner k's region)
};

const std::array<Vec3, 4> kCorner{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};

FaceInput make_face(const Square& sq) {
  FaceInput f;
  for (int k = 0; k < 4; ++k) {
    f.corners[k] = static_cast<int>(f.boundary.size());
    f.boundary.push_back({kCorner[k], sq.region[k], Vec3::Zero()});
    const Vec3 mid = 0.5 * (kCorner[k] + kCorner[(k + 1) % 4]);
    const auto push_point = [&] {
      if (sq.side[k]) f.boundary.push_back({sq.side[k]->first, kNoIndex, sq.side[k]->second.normalized()});
    };
    if (sq.midpoint[k]) {
      f.boundary.push_back({mid, sq.region[k], Vec3::Zero()});
      push_point();
    } else {
      push_point();
    }
  }
  return f;
}

std::vector<Vec3> points_of(const FaceInput& f, const FaceContour& c) {
  std::vector<Vec3> p;
  for (const BoundaryPoint& b : f.boundary) p.push_back(b.position);
  p.push_back(c.point);
  return p;
}

double polygon_area(const std::vector<Vec3>& points, const FacePolygon& poly) {
  return polygon_geometry(points, std::vector<Index>(poly.points.begin(), poly.points.end())).area_vector.z();
}

// Every polygon counter-clockwise, their areas add up to the face, each polygon's boundary
// points carry its region.
void expect_partition(const FaceInput& f, const FaceContour& c) {
  const std::vector<Vec3> p = points_of(f, c);
  double total = 0.0;
  for (const FacePolygon& poly : c.polygons) {
    const double a = polygon_area(p, poly);
    EXPECT_GT(a, 0.0);
    total += a;
    for (int i : poly.points)
      if (i < static_cast<int>(f.boundary.size()) && !f.boundary[i].is_interface()) {
        EXPECT_EQ(f.boundary[i].region, poly.region);
      }
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  for (const ContourSegment& s : c.segments) {
    ASSERT_GE(s.left_polygon, 0);
    ASSERT_GE(s.right_polygon, 0);
    EXPECT_EQ(c.polygons[s.left_polygon].region, s.left);
    EXPECT_EQ(c.polygons[s.right_polygon].region, s.right);
  }
}

// The polygon holding corner k.
int polygon_of_corner(const FaceInput& f, const FaceContour& c, int k) {
  for (std::size_t p = 0; p < c.polygons.size(); ++p)
    if (std::count(c.polygons[p].points.begin(), c.polygons[p].points.end(), f.corners[k])) return static_cast<int>(p);
  return -1;
}

TEST(FaceContour, UniformFaceIsOnePolygon) {
  const FaceInput f = make_face({{2, 2, 2, 2}, {}});
  const FaceContour c = contour_face(f);
  ASSERT_EQ(c.polygons.size(), 1u);
  EXPECT_TRUE(c.segments.empty());
  expect_partition(f, c);
}

TEST(FaceContour, OneCornerCutOff) {
  // The straight line through (0.4, 0) and (0, 0.3), normal (0.6, 0.8) out of region 1.
  Square sq{{1, 2, 2, 2}, {}};
  sq.side[0] = {{Vec3(0.4, 0, 0), Vec3(0.6, 0.8, 0)}};
  sq.side[3] = {{Vec3(0, 0.3, 0), Vec3(-0.6, -0.8, 0)}};  // from region 2 (corner 3) into 1
  const FaceInput f = make_face(sq);
  const FaceContour c = contour_face(f);
  EXPECT_EQ(c.kind, FacePointKind::none);
  ASSERT_EQ(c.polygons.size(), 2u);
  ASSERT_EQ(c.segments.size(), 1u);
  expect_partition(f, c);
  const std::vector<Vec3> p = points_of(f, c);
  EXPECT_NEAR(polygon_area(p, c.polygons[polygon_of_corner(f, c, 0)]), 0.5 * 0.4 * 0.3, 1e-12);
}

TEST(FaceContour, HangingVertexStaysOnItsPolygon) {
  Square sq{{1, 1, 2, 2}, {}};
  sq.midpoint[0] = true;
  sq.midpoint[1] = true;  // the interface point lies after it, on the second half
  sq.side[1] = {{Vec3(1, 0.7, 0), Vec3(0, 1, 0)}};
  sq.side[3] = {{Vec3(0, 0.7, 0), Vec3(0, -1, 0)}};
  const FaceInput f = make_face(sq);
  const FaceContour c = contour_face(f);
  ASSERT_EQ(c.polygons.size(), 2u);
  expect_partition(f, c);
  const std::vector<Vec3> p = points_of(f, c);
  const FacePolygon& low = c.polygons[polygon_of_corner(f, c, 0)];
  EXPECT_EQ(low.points.size(), 6u);  // 2 corners, 2 midpoints, 2 interface points
  EXPECT_NEAR(polygon_area(p, low), 0.7, 1e-12);
}

// A junction beside side 1: the side is crossed twice (a plane, then a line cutting corner
// 2 off), a vertex of the region between splits it. Each crossing keeps its own chord.
TEST(FaceContour, SideCrossedTwiceKeepsBothCrossings) {
  FaceInput f;
  const auto vertex = [&f](const Vec3& p, Index region) { f.boundary.push_back({p, region, Vec3::Zero()}); };
  const auto crossing = [&f](const Vec3& p, const Vec3& normal) { f.boundary.push_back({p, kNoIndex, normal}); };
  f.corners = {0, 1, 5, 7};
  vertex(kCorner[0], 0);
  vertex(kCorner[1], 0);
  crossing(Vec3(1, 0.3, 0), Vec3(0, 1, 0));  // into region 2 above the plane y = 0.3
  vertex(Vec3(1, 0.5, 0), 2);                 // the split vertex
  crossing(Vec3(1, 0.7, 0), Vec3(0.6, 0.8, 0));
  vertex(kCorner[2], 3);
  crossing(Vec3(0.6, 1, 0), Vec3(-0.6, -0.8, 0));
  vertex(kCorner[3], 2);
  crossing(Vec3(0, 0.3, 0), Vec3(0, -1, 0));
  const FaceContour c = contour_face(f);
  EXPECT_EQ(c.kind, FacePointKind::none);
  ASSERT_EQ(c.segments.size(), 2u);
  ASSERT_EQ(c.polygons.size(), 3u);
  expect_partition(f, c);
  const std::vector<Vec3> p = points_of(f, c);
  EXPECT_NEAR(polygon_area(p, c.polygons[polygon_of_corner(f, c, 0)]), 0.3, 1e-12);
  EXPECT_NEAR(polygon_area(p, c.polygons[polygon_of_corner(f, c, 2)]), 0.5 * 0.4 * 0.3, 1e-12);
  const FacePolygon& middle = c.polygons[polygon_of_corner(f, c, 3)];
  EXPECT_EQ(std::count(middle.points.begin(), middle.points.end(), 3), 1);
}

// A junction line passing just beside side 3 (the napkin circle of builtin:primitives, where
// the cylinder leaves the ball, 2e-4 above a grid face): side 3 is crossed twice closer than
// the split gap, one crossing standing for both with the thin region 4 between them
// pinched out. That crossing is the junction; the tangent lines at side 1's crossings,
// nearly parallel and tilted by the surfaces' curvature, meet half a face away.
TEST(FaceContour, PinchedCrossingIsTheJunction) {
  FaceInput f;
  const auto vertex = [&f](const Vec3& p, Index region) { f.boundary.push_back({p, region, Vec3::Zero()}); };
  const auto crossing = [&f](const Vec3& p, const Vec3& normal, Index pinched = kNoIndex) {
    f.boundary.push_back({p, kNoIndex, normal.normalized(), pinched});
  };
  f.corners = {0, 1, 5, 6};
  vertex(kCorner[0], 5);
  vertex(kCorner[1], 5);
  crossing(Vec3(1, 0.4697, 0), Vec3(0.02, 1, 0));  // into the wedge of region 4
  vertex(Vec3(1, 0.5, 0), 4);                       // the split vertex
  crossing(Vec3(1, 0.5303, 0), Vec3(-0.02, 1, 0));
  vertex(kCorner[2], 0);
  vertex(kCorner[3], 0);
  crossing(Vec3(0, 0.5003, 0), Vec3::Zero(), 4);     // 0 -> 4 -> 5 within 6e-4
  const FaceContour c = contour_face(f);
  ASSERT_EQ(c.kind, FacePointKind::interface_point);
  EXPECT_EQ(c.centre, 7);
  EXPECT_TRUE(c.point.isApprox(Vec3(0, 0.5003, 0)));
  expect_partition(f, c);
  const std::vector<Vec3> p = points_of(f, c);
  EXPECT_NEAR(polygon_area(p, c.polygons[polygon_of_corner(f, c, 0)]), 0.5 * (0.4697 + 0.5003), 1e-12);
}

// A CAD part's sharp edge (fandisk's) running along a side, just inside or just outside it
// (the vertex moves put it there): the feature point is kept on the kept polygon, pulled just
// inside the face when it lies beyond. Refused, the chord would cut the edge off by half a
// cell.
TEST(FaceContour, SharpEdgeAlongASideKeepsItsFeaturePoint) {
  for (const double offset : {5e-4, -5e-4}) {
    // Line b through (0.2, offset) with slope 0.05 (region 1 above), line a perpendicular.
    const Vec3 corner(0.2, offset, 0.0), along(1.0, 0.05, 0.0);
    const Vec3 across = Vec3(-0.05, 1.0, 0.0).normalized();
    Square sq{{0, 0, 1, 0}, {}};
    sq.side[1] = {{corner + 0.8 * along, across}};
    sq.side[2] = {{corner + (1.0 - offset) * Vec3(-0.05, 1.0, 0.0), -along.normalized()}};
    const FaceInput f = make_face(sq);
    const FaceContour c = contour_face(f);
    ASSERT_EQ(c.kind, FacePointKind::feature_point) << offset;
    EXPECT_NEAR(c.point.x(), 0.2, 2e-3) << offset;
    EXPECT_NEAR(c.point.y(), std::max(offset, 1e-3), 1e-4) << offset;
    expect_partition(f, c);
  }
}

// A concave sharp edge crossing the face 0.014 of the side from the left side, whose lower
// part stays in the kept region (fandisk at level 6): its feature point is kept, a thin spike
// of the kept polygon beside it; the chord from side to side would cut the edge off.
TEST(FaceContour, SharpEdgeBesideAKeptSideKeepsItsFeaturePoint) {
  const Vec3 left(0.0, 0.24, 0.0), feature(0.0136, 0.1695, 0.0), right(1.0, 0.1716, 0.0);
  const Vec3 a = feature - left, b = right - feature;
  Square sq{{1, 1, 0, 0}, {}};
  sq.side[3] = {{left, Vec3(-a.y(), a.x(), 0.0).normalized()}};
  sq.side[1] = {{right, Vec3(-b.y(), b.x(), 0.0).normalized()}};
  const FaceInput f = make_face(sq);
  const FaceContour c = contour_face(f);
  ASSERT_EQ(c.kind, FacePointKind::feature_point);
  EXPECT_LT((c.point - feature).norm(), 1e-9);
  expect_partition(f, c);
}

// Two regions on alternate corners: the tangent lines decide which corners connect.
Square ambiguous_square(bool blobs_at_corners) {
  Square sq{{1, 2, 1, 2}, {}};
  if (blobs_at_corners) {
    // Region 1 as discs around corners 0 and 2: the region-1 corners stay apart.
    sq.side[0] = {{Vec3(0.4, 0, 0), Vec3(1, 0, 0)}};
    sq.side[1] = {{Vec3(1, 0.6, 0), Vec3(0, 1, 0)}};
    sq.side[2] = {{Vec3(0.6, 1, 0), Vec3(-1, 0, 0)}};
    sq.side[3] = {{Vec3(0, 0.4, 0), Vec3(0, -1, 0)}};
  } else {
    // Region 1 as the band |x - y| < 0.6 along the diagonal: its corners connect.
    sq.side[0] = {{Vec3(0.6, 0, 0), Vec3(1, -1, 0)}};
    sq.side[1] = {{Vec3(1, 0.4, 0), Vec3(-1, 1, 0)}};
    sq.side[2] = {{Vec3(0.4, 1, 0), Vec3(-1, 1, 0)}};
    sq.side[3] = {{Vec3(0, 0.6, 0), Vec3(1, -1, 0)}};
  }
  return sq;
}

TEST(FaceContour, AmbiguityFollowsTheTangentLines) {
  for (const bool blobs : {true, false}) {
    const FaceInput f = make_face(ambiguous_square(blobs));
    const FaceContour c = contour_face(f);
    EXPECT_EQ(c.kind, FacePointKind::none);
    ASSERT_EQ(c.polygons.size(), 3u);
    ASSERT_EQ(c.segments.size(), 2u);
    expect_partition(f, c);
    const bool ones_joined = polygon_of_corner(f, c, 0) == polygon_of_corner(f, c, 2);
    const bool twos_joined = polygon_of_corner(f, c, 1) == polygon_of_corner(f, c, 3);
    EXPECT_EQ(ones_joined, !blobs) << (blobs ? "discs" : "band");
    EXPECT_EQ(twos_joined, blobs) << (blobs ? "discs" : "band");
  }
}

TEST(FaceContour, ThreeRegionsWithEqualDiagonalConnectIt) {
  Square sq{{1, 2, 1, 3}, {}};
  sq.side[0] = {{Vec3(0.6, 0, 0), Vec3(1, -1, 0)}};
  sq.side[1] = {{Vec3(1, 0.4, 0), Vec3(-1, 1, 0)}};
  sq.side[2] = {{Vec3(0.4, 1, 0), Vec3(-1, 1, 0)}};
  sq.side[3] = {{Vec3(0, 0.6, 0), Vec3(1, -1, 0)}};
  const FaceInput f = make_face(sq);
  const FaceContour c = contour_face(f);
  EXPECT_EQ(c.kind, FacePointKind::none);
  ASSERT_EQ(c.polygons.size(), 3u);
  expect_partition(f, c);
  EXPECT_EQ(polygon_of_corner(f, c, 0), polygon_of_corner(f, c, 2));
}

// A T-junction: region 1 on x < 0.5, regions 2 (y < 0.5) and 3 (y > 0.5) on x > 0.5.
Square t_junction() {
  Square sq{{1, 2, 3, 1}, {}};
  sq.side[0] = {{Vec3(0.5, 0, 0), Vec3(1, 0, 0)}};
  sq.side[1] = {{Vec3(1, 0.5, 0), Vec3(0, 1, 0)}};
  sq.side[2] = {{Vec3(0.5, 1, 0), Vec3(-1, 0, 0)}};
  return sq;
}

TEST(FaceContour, FaceInterfacePointIsTheTangentIntersection) {
  const FaceInput f = make_face(t_junction());
  const FaceContour c = contour_face(f);
  EXPECT_EQ(c.kind, FacePointKind::interface_point);
  EXPECT_FALSE(c.point_left_face);
  EXPECT_LT((c.point - Vec3(0.5, 0.5, 0)).norm(), 1e-12);
  ASSERT_EQ(c.polygons.size(), 3u);
  EXPECT_EQ(c.segments.size(), 3u);
  expect_partition(f, c);
  const std::vector<Vec3> p = points_of(f, c);
  EXPECT_NEAR(polygon_area(p, c.polygons[polygon_of_corner(f, c, 0)]), 0.5, 1e-12);
  EXPECT_NEAR(polygon_area(p, c.polygons[polygon_of_corner(f, c, 1)]), 0.25, 1e-12);
}

TEST(FaceContour, FourRegionsMeetAtTheFaceInterfacePoint) {
  Square sq{{1, 2, 3, 4}, {}};
  sq.side[0] = {{Vec3(0.3, 0, 0), Vec3(1, 0, 0)}};
  sq.side[1] = {{Vec3(1, 0.6, 0), Vec3(0, 1, 0)}};
  sq.side[2] = {{Vec3(0.3, 1, 0), Vec3(-1, 0, 0)}};
  sq.side[3] = {{Vec3(0, 0.6, 0), Vec3(0, -1, 0)}};
  const FaceInput f = make_face(sq);
  const FaceContour c = contour_face(f);
  EXPECT_EQ(c.kind, FacePointKind::interface_point);
  EXPECT_LT((c.point - Vec3(0.3, 0.6, 0)).norm(), 1e-12);
  EXPECT_EQ(c.polygons.size(), 4u);
  expect_partition(f, c);
}

TEST(FaceContour, FacePointOutsideTheFaceFallsBackToTheCentroid) {
  // Tangent lines that meet far outside the face.
  // Tangent lines meeting at (0.5, -0.5), a half side below the face.
  Square sq = t_junction();
  sq.side[1]->second = Vec3(1, -0.5, 0);
  const FaceInput f = make_face(sq);
  const FaceContour c = contour_face(f);
  EXPECT_TRUE(c.point_left_face);
  EXPECT_LT((c.point - Vec3(2.0 / 3.0, 0.5, 0)).norm(), 1e-12);
  expect_partition(f, c);
}

TEST(FaceContour, FacePointAtASideLandsOnItsEdgePoint) {
  // The junction meets the face right next to side 0's interface point (0.5, 0).
  Square sq{{1, 2, 3, 1}, {}};
  sq.side[0] = {{Vec3(0.5, 0, 0), Vec3(1, 0, 0)}};
  sq.side[1] = {{Vec3(1, 0.02, 0), Vec3(-0.02, 1, 0)}};
  sq.side[2] = {{Vec3(0.5, 1, 0), Vec3(-1, 0, 0)}};
  const FaceInput f = make_face(sq);
  const FaceContour c = contour_face(f);
  EXPECT_EQ(c.kind, FacePointKind::interface_point);
  ASSERT_GE(c.centre, 0);
  EXPECT_LT((f.boundary[c.centre].position - Vec3(0.5, 0, 0)).norm(), 1e-12);
  EXPECT_EQ(c.segments.size(), 2u);
  EXPECT_EQ(c.polygons.size(), 3u);
  expect_partition(f, c);
}

TEST(FaceContour, SharpCornerGetsAFeaturePoint) {
  // Region 1 = {x < 0.7, y < 0.6}: a box corner inside the face.
  Square sq{{1, 0, 0, 0}, {}};
  sq.side[0] = {{Vec3(0.7, 0, 0), Vec3(1, 0, 0)}};
  sq.side[3] = {{Vec3(0, 0.6, 0), Vec3(0, -1, 0)}};
  const FaceInput f = make_face(sq);
  const FaceContour c = contour_face(f);
  EXPECT_EQ(c.kind, FacePointKind::feature_point);
  EXPECT_LT((c.point - Vec3(0.7, 0.6, 0)).norm(), 1e-12);
  EXPECT_EQ(c.segments.size(), 2u);
  expect_partition(f, c);
  const std::vector<Vec3> p = points_of(f, c);
  EXPECT_NEAR(polygon_area(p, c.polygons[polygon_of_corner(f, c, 0)]), 0.42, 1e-12);
}

// Region 1 = the disc of radius 0.8 about corner 0, a bend of 90 degrees within the face (a
// coarse model's facets turning about one per cell): the tangent lines meet at (0.8, 0.8),
// 0.33 beyond the arc, and the Newton step finds no two surfaces meeting there. The feature
// point goes onto the arc, found along the traces' mean normal.
TEST(FaceContour, ARoundedBendPutsTheFeaturePointOnTheSurface) {
  const double r = 0.8;
  Square sq{{1, 0, 0, 0}, {}};
  sq.side[0] = {{Vec3(r, 0, 0), Vec3(1, 0, 0)}};
  sq.side[3] = {{Vec3(0, r, 0), Vec3(0, -1, 0)}};
  const FaceInput f = make_face(sq);
  FaceContourOptions options;
  // The circle's crossing of x -+ d nearest x whose outward normal lies within about 26
  // degrees of d (kSameSurfaceCosine).
  options.surface_near = [r](const Vec3& x, const Vec3& d) -> std::optional<std::pair<Vec3, Vec3>> {
    const Vec3 a = x - d, b = x + d, ab = b - a;
    const double qa = ab.squaredNorm(), qb = 2.0 * a.dot(ab), qc = a.squaredNorm() - r * r;
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0) return std::nullopt;
    std::optional<std::pair<Vec3, Vec3>> best;
    for (const double t : {(-qb - std::sqrt(disc)) / (2.0 * qa), (-qb + std::sqrt(disc)) / (2.0 * qa)}) {
      const Vec3 p = a + t * ab, n = p.normalized();
      if (t < 0.0 || t > 1.0 || !(n.dot(d.normalized()) > kSameSurfaceCosine)) continue;
      if (!best || (p - x).norm() < (best->first - x).norm()) best = {p, n};
    }
    return best;
  };
  const FaceContour c = contour_face(f, options);
  ASSERT_EQ(c.kind, FacePointKind::feature_point);
  EXPECT_NEAR(c.point.norm(), r, 1e-12);
  EXPECT_NEAR(c.point.x(), c.point.y(), 1e-12);
  expect_partition(f, c);
}

TEST(FaceContour, PublishedM3CPutsTheFacePointAtTheCentre) {
  FaceContourOptions options;
  options.exact_points = false;
  const FaceInput f = make_face(t_junction());
  const FaceContour c = contour_face(f, options);
  EXPECT_LT((c.point - Vec3(0.5, 0.5, 0)).norm(), 1e-12);
  Square corner{{1, 0, 0, 0}, {}};
  corner.side[0] = {{Vec3(0.5, 0, 0), Vec3(1, 0, 0)}};
  corner.side[3] = {{Vec3(0, 0.5, 0), Vec3(0, -1, 0)}};
  EXPECT_EQ(contour_face(make_face(corner), options).kind, FacePointKind::none);
}

}  // namespace
}  // namespace volmesh::cutcell
