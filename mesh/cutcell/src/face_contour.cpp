// M3S with the exact interface points of MMCMS: marching squares for two regions (the
// four-point ambiguity resolved by the normals), the diagonal rule for three regions with
// equal opposite corners, otherwise a face interface point at the least-squares intersection
// of the tangent lines (centroid of the interface points when it leaves the face).
#include "face_contour.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "curve_crossing.hpp"
#include "tangent_point.hpp"
#include "volmesh/core/geometry.hpp"

namespace volmesh::cutcell {
namespace {

// Two surfaces whose normals' cosine is below this in magnitude meet at a sharp edge.
constexpr double kRightAngle = 0.5;
// A feature point within kSideSlackReach times this fraction of the side outside its face,
// or less than it inside, is moved to this depth.
constexpr double kSideSlack = 1e-3;
constexpr double kSideSlackReach = 10.0;
// A sharp edge's feature point keeps this fraction of the side from the kept polygon's sides,
// less than the margin (which is for the points of curved surfaces): an edge crossing the
// face just beside a side whose end is kept (a CAD part's edge along a grid plane) keeps
// its point, which the cell's feature fan needs, and leaves a thin but proper spike of the
// kept polygon.
constexpr double kSideClearance = 1e-2;
// The least-squares fits here fix at most two directions: those of the face's plane for the
// tangent lines in it, those across a sharp edge for the planes of its two surfaces.
constexpr int kFitRank = 2;
// A projected normal shorter than this (a normal along the face's own) gives no direction in
// the face.
constexpr double kMinInPlane = 1e-12;
// Pushing a point off one side may push it toward a neighbouring side of a face that vertex
// moves warped; this many passes over the four sides settle it.
constexpr int kClampPasses = 3;
// onto_feature's Newton step: each surface is sought on a segment kNewtonReach of the face
// either way, centred kShiftOfReach of that reach (a tenth of the face) along the surface
// away from the edge; it needs the two normals at least 30 degrees apart (each one's part
// across the other at least kMinAcross) and is taken only when it moves the point less than
// kSmallStep of the face.
constexpr double kNewtonReach = 0.25;
constexpr double kShiftOfReach = 0.4;
constexpr double kMinAcross = 0.5;
constexpr double kSmallStep = 0.05;
// onto_rounded_bend moves the point onto a surface found farther than this fraction of the
// face from it: nearer, the tangent planes' meeting point is as good.
constexpr double kBendDepth = 0.1;
// An X-junction (two interfaces crossing in the face): the opposite crossings of one surface
// have normals within 60 degrees of each other (cosine above kSameCurveCosine), the two
// surfaces' normals differ by more than about 18 degrees (cosine below kTransversalCosine).
constexpr double kSameCurveCosine = 0.5;
constexpr double kTransversalCosine = 0.95;

struct Frame {
  Vec3 centre, normal;
  std::array<Vec3, 4> corner;
  double size;  // side length
};

Frame face_frame(const FaceInput& face) {
  Frame f;
  f.centre = Vec3::Zero();
  for (int k = 0; k < 4; ++k) {
    f.corner[k] = face.boundary[face.corners[k]].position;
    f.centre += 0.25 * f.corner[k];
  }
  const Vec3 area = (f.corner[2] - f.corner[0]).cross(f.corner[3] - f.corner[1]);
  f.size = std::sqrt(0.5 * area.norm());
  f.normal = area.normalized();
  return f;
}

Vec3 in_plane(const Vec3& v, const Vec3& normal) { return v - v.dot(normal) * normal; }

// Distance of p inside the face from its nearest side (negative outside), in the face plane.
double depth_inside(const Frame& f, const Vec3& p) {
  double depth = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 4; ++k) {
    const Vec3 side = in_plane(f.corner[(k + 1) % 4] - f.corner[k], f.normal);
    const Vec3 inward = f.normal.cross(side).normalized();
    depth = std::min(depth, inward.dot(p - f.corner[k]));
  }
  return depth;
}

// p pushed into the face until it lies margin inside every side; nullopt when p lies
// farther than `reach` outside it.
std::optional<Vec3> clamp_into(const Frame& f, Vec3 p, double margin, double reach) {
  if (depth_inside(f, p) < -reach) return std::nullopt;
  for (int pass = 0; pass < kClampPasses; ++pass)
    for (int k = 0; k < 4; ++k) {
      const Vec3 side = in_plane(f.corner[(k + 1) % 4] - f.corner[k], f.normal);
      const Vec3 inward = f.normal.cross(side).normalized();
      const double d = inward.dot(p - f.corner[k]);
      if (d < margin) p += (margin - d) * inward;
    }
  return p;
}

class Contourer {
 public:
  Contourer(const FaceInput& face, const FaceContourOptions& options)
      : face_(face), options_(options), n_(static_cast<int>(face.boundary.size())),
        frame_(face_frame(face)) {}

  FaceContour run();

 private:
  const BoundaryPoint& at(int i) const { return face_.boundary[(i + n_) % n_]; }
  Index region_before(int i) const { return at(i - 1).region; }
  Index region_after(int i) const { return at(i + 1).region; }
  Vec3 projected_normal(int i) const {
    const Vec3 m = in_plane(at(i).normal, frame_.normal);
    const double len = m.norm();
    return len > kMinInPlane ? Vec3(m / len) : Vec3::Zero();
  }
  Vec3 tangent_point(const std::vector<int>& points) const;
  int pinched_point() const;
  std::optional<Vec3> x_junction() const;
  Vec3 onto_feature(int p, int q, Vec3 x) const;
  Vec3 onto_rounded_bend(int p, int q, const Vec3& x) const;
  Vec3 onto_boundary(const std::vector<int>& points, const Vec3& p) const;
  void chord(int p, int q);
  void star();
  void walk_polygons();
  bool keeps_margin(int p, int q, const Vec3& point) const;
  bool try_feature_point(int p, int q);
  int nearest_side_point(const Vec3& p) const;
  double chord_agreement(int p, int q) const;
  int face_point_index() const { return n_; }

  const FaceInput& face_;
  const FaceContourOptions& options_;
  const int n_;
  const Frame frame_;
  std::vector<int> crossing_;  // interface points in boundary order
  std::array<std::vector<int>, 4> side_points_;  // the interface points of each side
  std::vector<int> partner_;   // chord partner of a boundary point, -1 if none
  std::vector<char> via_point_;  // the chord from this point passes through the face point
  FaceContour out_;
};

// The least-squares intersection of the tangent lines at these interface points, those of
// the domain's boundary (region 0 on one side) fitted first; then moved onto the boundary's
// tangent planes in space: on a face warped by vertex moves the lines in its mean plane
// miss a planar boundary.
Vec3 Contourer::tangent_point(const std::vector<int>& points) const {
  std::vector<Vec3> s, m;
  std::vector<std::uint8_t> level;
  for (int i : points) {
    s.push_back(at(i).position);
    m.push_back(projected_normal(i));
    level.push_back(region_before(i) == 0 || region_after(i) == 0 ? 0 : 1);
  }
  return onto_boundary(points, tangent_intersection_ranked(s, m, level, kFitRank));
}

// p moved least onto the domain's boundary planes at these interface points (p itself when
// none crosses the face).
Vec3 Contourer::onto_boundary(const std::vector<int>& points, const Vec3& p) const {
  std::vector<Vec3> s, m;
  for (int i : points)
    if (region_before(i) == 0 || region_after(i) == 0)
      if (!at(i).normal.isZero()) {
        s.push_back(at(i).position);
        m.push_back(at(i).normal);
      }
  // Only planes the octree's faces are parallel to (a box): on a curved boundary the lines
  // in the face are as good, and moving the point off them can fold the faces around it.
  return s.empty() || !std::all_of(m.begin(), m.end(), parallel_to_octree_faces) ? p
                                                                                : tangent_intersection(s, m, p, kFitRank);
}

// How well the chord p -> q agrees with the tangent lines at its ends: the normal at each
// end should point from the chord's left region into its right one. The ambiguous
// two-region face takes the pairing that agrees best.
double Contourer::chord_agreement(int p, int q) const {
  const Vec3 d = in_plane(at(q).position - at(p).position, frame_.normal);
  const double len = d.norm();
  if (len == 0.0) return 0.0;
  const Vec3 right = d.cross(frame_.normal) / len;
  // Left of p -> q is the region before p; at q the region before q lies on the right.
  return projected_normal(p).dot(right) - projected_normal(q).dot(right);
}

// Whether a feature point on the chord p -> q keeps the margin from the sides. At a sharp
// edge of the domain's boundary only the kept polygon's sides count: the point may lie deep
// in the corner of the face, beside the outside corner alone (a box's face just off a grid
// plane, its vertices moved across it), or along a side (an edge of a CAD part, fandisk's,
// that the vertex moves put on the side), and there the outside polygon's sliver is dropped
// with it. A sharp edge here: one surface is a plane parallel to the octree's faces, or the
// two meet at nearly a right angle. It need only keep kSideClearance from the kept polygon's
// sides. On a curved surface a tangent intersection that near a side is no feature (a torus's).
bool Contourer::keeps_margin(int p, int q, const Vec3& point) const {
  const double margin = options_.margin * frame_.size;
  const double depth = depth_inside(frame_, point);
  if (depth >= margin) return true;
  const Index before = region_before(p), after = region_after(p);
  const bool sharp = parallel_to_octree_faces(at(p).normal) || parallel_to_octree_faces(at(q).normal) ||
                     std::abs(at(p).normal.dot(at(q).normal)) < kRightAngle;
  if (depth <= 0.0 || (before != 0 && after != 0) || !sharp) return false;
  // The kept polygon's boundary runs from p to q when it lies after p, else from q to p.
  const int from = after != 0 ? p : q, to = after != 0 ? q : p;
  for (int i = from; i % n_ != to; ++i) {
    const Vec3& a = at(i).position;
    // In the face plane, relative to a.
    const Vec3 p = in_plane(point - a, frame_.normal), b = in_plane(at(i + 1).position - a, frame_.normal);
    if (distance_to_segment(p, Vec3::Zero(), b) < kSideClearance * frame_.size) return false;
  }
  return true;
}

// The feature point of the surfaces through edge points p and q, from their traces' meeting
// point x in the face's mean plane, put on the sharp edge itself:
// - On a face warped by the vertex moves, nearly parallel to one of the tangent planes, the
//   traces meet off the edge: x goes to the nearest point of the planes' intersection (no
//   move on a plane face, where the traces meet on it).
// - Then, given surface_near and off the root's boundary (a point between two layers there
//   must stay in the box's plane), one Newton step: each surface found again beside x (along
//   its normal moved into the other's tangent plane, kNewtonReach of the face either way,
//   shifted along the surface away from the edge: on the other surface's plane the segment
//   could run along it) and x moved to where the new tangent planes meet (kept on the
//   domain's boundary planes, as tangent_point keeps it), unless the step is not small.
Vec3 Contourer::onto_feature(int p, int q, Vec3 x) const {
  // Both normals out of the region before p (the one after q).
  const Vec3 na = at(p).normal, nb = -at(q).normal;
  if (na.isZero() || nb.isZero()) return x;
  x = tangent_intersection(std::array<Vec3, 2>{at(p).position, at(q).position}, std::array<Vec3, 2>{na, nb}, x, kFitRank);
  if (!options_.surface_near || face_.on_root) return x;
  // The surfaces bound the region they point into where both normals point into it from
  // the chord p-q (it is convex at the edge), else where either does.
  const Vec3 mid = 0.5 * (at(p).position + at(q).position);
  const double side = na.dot(mid - x) + nb.dot(mid - x) > 0.0 ? 1.0 : -1.0;
  const double reach = kNewtonReach * frame_.size;
  std::array<Vec3, 2> s, n;
  for (int k = 0; k < 2; ++k) {
    const Vec3 &own = k == 0 ? na : nb, &other = k == 0 ? nb : na;
    const Vec3 along = own - own.dot(other) * other;
    if (!(along.norm() > kMinAcross)) return x;
    const auto found = options_.surface_near(x + side * kShiftOfReach * reach * other, reach * along.normalized());
    if (!found || !(found->second.dot(own) > kSameSurfaceCosine)) return x;
    s[k] = found->first;
    n[k] = found->second;
  }
  const Vec3 refined = onto_boundary({p, q}, tangent_intersection(s, n, x, kFitRank));
  return (refined - x).norm() < kSmallStep * frame_.size ? refined : x;
}

// A bend rounded over several of a coarse surface's facets (elephant's, about one per cell):
// the planes of the facets at p and q meet beyond the surface between them, there by up to
// half the face, and the Newton step found no two surfaces meeting there. When the surface
// found from x along the traces' mean normal, within a face either way, lies farther than
// kBendDepth of the face, x goes onto it: both segments then lie on the surface's side of it.
Vec3 Contourer::onto_rounded_bend(int p, int q, const Vec3& x) const {
  if (!options_.surface_near || face_.on_root) return x;
  const Vec3 d = in_plane(at(p).normal - at(q).normal, frame_.normal);  // both out of the region before p
  if (!(d.norm() > kMinInPlane)) return x;
  const auto found = options_.surface_near(x, frame_.size * d.normalized());
  return found && (found->first - x).norm() > kBendDepth * frame_.size ? found->first : x;
}

bool Contourer::try_feature_point(int p, int q) {
  const Vec3 mp = projected_normal(p), mq = projected_normal(q);
  // mp points from region A into B, mq from B into A: a straight interface has mp = -mq.
  if (mp.isZero() || mq.isZero() || !(mp.dot(-mq) < options_.feature_theta)) return false;
  Vec3 point = onto_rounded_bend(p, q, onto_feature(p, q, tangent_point({p, q})));
  // An edge on the side (to rounding, or moved there by the vertex moves) comes out on it or
  // just beyond: pulled just inside, it keeps the face's polygons apart.
  const double depth = depth_inside(frame_, point), slack = kSideSlack * frame_.size;
  const double reach = kSideSlackReach * slack;
  if (depth < slack && depth > -reach) point = *clamp_into(frame_, point, slack, reach);
  if (!keeps_margin(p, q, point)) return false;
  out_.kind = FacePointKind::feature_point;
  out_.point = point;
  return true;
}

void Contourer::chord(int p, int q) {
  partner_[p] = q;
  partner_[q] = p;
  const Index left = region_before(p), right = region_after(p);
  if (options_.exact_points && out_.kind == FacePointKind::none && crossing_.size() == 2 &&
      try_feature_point(p, q)) {
    via_point_[p] = via_point_[q] = 1;
    out_.segments.push_back({p, face_point_index(), left, right});
    out_.segments.push_back({face_point_index(), q, left, right});
    return;
  }
  out_.segments.push_back({p, q, left, right});
}

// The side nearest p (in the face plane) and its interface point nearest p, -1 if it has none.
int Contourer::nearest_side_point(const Vec3& p) const {
  int best = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 4; ++k) {
    const Vec3 side = in_plane(frame_.corner[(k + 1) % 4] - frame_.corner[k], frame_.normal);
    const double d = frame_.normal.cross(side).normalized().dot(p - frame_.corner[k]);
    if (d < nearest) {
      nearest = d;
      best = k;
    }
  }
  int point = -1;
  for (int i : side_points_[best])
    if (point < 0 || (at(i).position - p).norm() < (at(point).position - p).norm()) point = i;
  return point;
}

// The interface point of a three-region junction that stands for two crossings (a side
// still crossed twice at the deepest level, its crossings not both kept) of the third
// region, or -1. That region pinches out there: the junction meets the side within the gap, where
// the tangent lines of the other points, nearly parallel beside a junction line running
// along the face, meet anywhere.
int Contourer::pinched_point() const {
  if (crossing_.size() != 3) return -1;
  for (int i : crossing_) {
    const Index middle = at(i).pinched;
    if (middle == kNoIndex) continue;
    for (int j : crossing_)
      if (j != i && (region_before(j) == middle || region_after(j) == middle)) return i;
  }
  return -1;
}

// Two interfaces crossing in the face (four crossings, the opposite ones on the same surface:
// their normals along the boundary opposite, the two surfaces' transversal): where the
// curves through each pair cross.
std::optional<Vec3> Contourer::x_junction() const {
  if (crossing_.size() != 4) return std::nullopt;
  std::array<CurveEnds, 2> curves;
  for (int k = 0; k < 2; ++k) {
    const int i = crossing_[k], j = crossing_[k + 2];
    const Vec3 ni = projected_normal(i), nj = -projected_normal(j);
    if (ni.isZero() || nj.isZero() || !(ni.dot(nj) > kSameCurveCosine)) return std::nullopt;
    curves[k] = {{at(i).position, at(j).position}, {ni, nj}};
  }
  if (!(std::abs(curves[0].normal[0].dot(curves[1].normal[0])) < kTransversalCosine)) return std::nullopt;
  return crossing_of_curves(curves[0], curves[1], frame_.normal);
}

// The face interface point joined to every edge point. When the least-squares point lies at
// a side (the junction meets the face next to its edge), it lands on that side's edge point
// if there is one (§3.3: the two coincide), otherwise it is pushed inside.
void Contourer::star() {
  out_.kind = FacePointKind::interface_point;
  int centre = face_point_index();
  if (!options_.exact_points) {
    out_.point = frame_.centre;
  } else if (const int pinched = pinched_point(); pinched >= 0) {
    centre = pinched;
    out_.point = at(pinched).position;
  } else {
    const std::optional<Vec3> crossing = x_junction();
    const Vec3 p = crossing ? *crossing : tangent_point(crossing_);
    const double margin = options_.margin * frame_.size, reach = options_.reach * frame_.size;
    const int side_point = nearest_side_point(p);
    if (depth_inside(frame_, p) >= margin) {
      out_.point = p;
    } else if (side_point >= 0 && (at(side_point).position - p).norm() <= reach) {
      centre = side_point;
      out_.point = at(side_point).position;
    } else if (const std::optional<Vec3> q = clamp_into(frame_, p, margin, reach)) {
      out_.point = *q;
    } else {
      out_.point_left_face = true;
      Vec3 mass = Vec3::Zero();
      for (int i : crossing_) mass += at(i).position / static_cast<double>(crossing_.size());
      out_.point = onto_boundary(crossing_, mass);
    }
  }
  if (centre != face_point_index()) out_.centre = centre;
  const int m = static_cast<int>(crossing_.size());
  for (int k = 0; k < m; ++k) {
    const int x = crossing_[k], next = crossing_[(k + 1) % m];
    if (x != centre) {
      out_.segments.push_back({x, centre, region_before(x), region_after(x), -1, k});
      out_.segments.back().left_polygon = (k + m - 1) % m;
    }
    FacePolygon poly{region_after(x), {}};
    for (int i = x; i != next; i = (i + 1) % n_) poly.points.push_back(i);
    poly.points.push_back(next);
    if (centre != x && centre != next) poly.points.push_back(centre);
    out_.polygons.push_back(std::move(poly));
  }
}

// Traces the polygons bounded by the sides and the chords: along the boundary until a chord
// end, across the chord, on along the boundary from its other end.
void Contourer::walk_polygons() {
  std::vector<char> used(n_, 0);  // boundary piece i -> i+1 traced
  for (int start = 0; start < n_; ++start) {
    if (used[start]) continue;
    const int index = static_cast<int>(out_.polygons.size());
    FacePolygon poly{kNoIndex, {}};
    int i = start;
    do {
      poly.points.push_back(i);
      used[i] = 1;
      if (poly.region == kNoIndex && !at(i).is_interface()) poly.region = at(i).region;
      const int j = (i + 1) % n_;
      if (partner_[j] >= 0) {
        poly.points.push_back(j);
        if (via_point_[j]) poly.points.push_back(face_point_index());
        for (ContourSegment& s : out_.segments) {
          if (s.a == j) s.left_polygon = index;
          if (s.b == j) s.right_polygon = index;
          if (via_point_[j] && s.a == face_point_index() && s.b == partner_[j]) s.left_polygon = index;
          if (via_point_[j] && s.b == face_point_index() && s.a == partner_[j]) s.right_polygon = index;
        }
        i = partner_[j];
      } else {
        i = j;
      }
    } while (i != start);
    if (poly.region == kNoIndex) poly.region = at((start + 1) % n_).region;
    out_.polygons.push_back(std::move(poly));
  }
}

FaceContour Contourer::run() {
  for (int i = 0; i < n_; ++i)
    if (at(i).is_interface()) {
      if (at(i - 1).is_interface() || at(i + 1).is_interface() || region_before(i) == region_after(i))
        throw std::logic_error("contour_face: an interface point not between two regions");
      crossing_.push_back(i);
    } else if (!at(i + 1).is_interface() && at(i).region != region_after(i)) {
      throw std::logic_error("contour_face: a change of region without its interface point");
    }
  for (int k = 0; k < 4; ++k) {
    const int end = k == 3 ? face_.corners[0] + n_ : face_.corners[k + 1];
    for (int i = face_.corners[k] + 1; i < end; ++i)
      if (at(i).is_interface()) side_points_[k].push_back(i % n_);
  }
  partner_.assign(n_, -1);
  via_point_.assign(n_, 0);

  std::vector<Index> distinct;
  for (int i = 0; i < n_; ++i)
    if (!at(i).is_interface()) distinct.push_back(at(i).region);
  std::sort(distinct.begin(), distinct.end());
  const int regions = static_cast<int>(std::unique(distinct.begin(), distinct.end()) - distinct.begin());
  const int np = static_cast<int>(crossing_.size());
  if (np > 4) throw std::logic_error("contour_face: more than four interface points");

  if (np == 0) {
    FacePolygon poly{at(0).region, {}};
    for (int i = 0; i < n_; ++i) poly.points.push_back(i);
    out_.polygons.push_back(std::move(poly));
    return std::move(out_);
  }
  if (np == 3 || (np == 4 && regions == 4)) {
    star();
    return std::move(out_);
  }
  const std::vector<int>& c = crossing_;
  if (np == 2) {
    chord(c[0], c[1]);
  } else {
    // Four interface points, two or three regions; arc k runs from point k to point k+1.
    // Cutting arcs 3 and 1 off pairs (3, 0) and (1, 2).
    const auto arc = [&](int k) { return region_after(c[k]); };
    bool cut_odd_arcs;
    if (regions == 3) {
      cut_odd_arcs = arc(0) == arc(2);  // keep the region of two opposite arcs connected
    } else {
      const double even = chord_agreement(c[3], c[0]) + chord_agreement(c[1], c[2]);
      const double odd = chord_agreement(c[0], c[1]) + chord_agreement(c[2], c[3]);
      cut_odd_arcs = even != odd ? even > odd : arc(3) < arc(0);  // tie: keep the higher label connected
    }
    if (cut_odd_arcs) {
      chord(c[3], c[0]);
      chord(c[1], c[2]);
    } else {
      chord(c[0], c[1]);
      chord(c[2], c[3]);
    }
  }
  walk_polygons();
  return std::move(out_);
}

}  // namespace

FaceContour contour_face(const FaceInput& face, const FaceContourOptions& options) {
  return Contourer(face, options).run();
}

}  // namespace volmesh::cutcell
