#pragma once
// M3S on one grid face (the octree paper, §2-3.3): the piecewise-linear contour of the
// interfaces on a square face and the polygons it cuts the face into, one region each.
#include <array>
#include <optional>
#include <cstdint>
#include <vector>

#include "tangent_point.hpp"
#include "volmesh/core/feature_angle.hpp"
#include "volmesh/core/types.hpp"

namespace volmesh::cutcell {

// A point on the boundary of a face: a grid vertex (a corner, a hanging vertex in the
// middle of a side, or a vertex splitting a side between its two crossings) or an edge
// interface point.
struct BoundaryPoint {
  Vec3 position = Vec3::Zero();
  Index region = kNoIndex;     // grid vertices: their region; interface points: kNoIndex
  Vec3 normal = Vec3::Zero();  // interface points: unit normal from the region before the
                               // point (in boundary order) into the region after it; zero
                               // when unknown (the point is then left out of the fits)
  // An interface point standing for two crossings: the region between them, else kNoIndex.
  Index pinched = kNoIndex;
  bool is_interface() const { return region == kNoIndex; }
};

// The boundary of a face counter-clockwise about its normal (the right-hand normal of the
// corners). An interface point lies between two grid vertices of different regions, and
// every change of region along the boundary has one; at most four in all. A side holds two
// when a vertex between them splits it (an edge crossed twice).
struct FaceInput {
  std::vector<BoundaryPoint> boundary;
  std::array<int, 4> corners{};  // positions of the corners in `boundary`, increasing
  // On the octree root's boundary (a box domain's face): its points stay in its plane.
  bool on_root = false;
};

struct FaceContourOptions {
  // false: M3C as published (Wu & Sullivan): the face interface point at the face centre,
  // no feature points; the edge points are then edge midpoints, given by the caller.
  bool exact_points = true;
  double feature_theta = kFeatureCosine;  // sharp when the tangents' cosine is below (CMS, Fig. 4b)
  // Face points keep margin * side away from the sides. A face interface point found nearer
  // a side, or outside by less than reach * side, lands on that side's edge point when
  // there is one within reach, or is pushed in; farther out it has left the face.
  double margin = 0.05;
  double reach = 0.25;
  // Given (exact points), a feature point takes one Newton step onto the true surfaces:
  // found from tangent planes a face's width away, it is off a curved one by d^2 / 2r.
  SurfaceNear surface_near;
};

enum class FacePointKind : std::uint8_t {
  none,
  interface_point,  // three or four regions meet on the face
  feature_point,    // two regions, a sharp bend of their interface inside the face
};

// Point indices: 0..boundary.size()-1 are the boundary points, boundary.size() is the face
// point (when there is one).
struct ContourSegment {
  int a = 0, b = 0;
  Index left = 0, right = 0;  // regions on either side of a -> b, seen from the normal side
  int left_polygon = -1, right_polygon = -1;
};
struct FacePolygon {
  Index region = 0;
  std::vector<int> points;  // counter-clockwise about the face normal
};
struct FaceContour {
  FacePointKind kind = FacePointKind::none;
  Vec3 point = Vec3::Zero();
  // An interface point that landed on an edge point: the boundary index of that point (no
  // new point then); -1 otherwise.
  int centre = -1;
  bool point_left_face = false;  // the least-squares point left the face: the fallback was used
  std::vector<ContourSegment> segments;
  std::vector<FacePolygon> polygons;
};

FaceContour contour_face(const FaceInput& face, const FaceContourOptions& options = {});

}  // namespace volmesh::cutcell
