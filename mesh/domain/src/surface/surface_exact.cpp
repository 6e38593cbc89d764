// Exact segment queries: CGAL's AABB tree (Epick: its segment-box test is an exact
// predicate) for the candidates, CGAL's filtered orientation predicates for the rest.
#include "surface_exact.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace volmesh::surface {

namespace {

// The first rays of the winding number run along the axes tilted by these slopes (no simple
// fractions), so that they miss the edges and vertices of axis-aligned meshes.
constexpr double kRayTilt1 = 0.0731, kRayTilt2 = 0.0417;
// A ray ends this fraction of the surfaces' box diagonal beyond the box.
constexpr double kRayBeyond = 1e-3;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
using Traits = CGAL::AABB_traits<Kernel, Primitive>;
using Tree = CGAL::AABB_tree<Traits>;

Point point(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

int sign(CGAL::Orientation o) { return o == CGAL::POSITIVE ? 1 : o == CGAL::NEGATIVE ? -1 : 0; }

// Collects the triangles under the nodes whose box meets the segment's box (CGAL's
// traversal tests the boxes of inner nodes only). A superset of the triangles the segment
// meets, which the classification picks out: comparing boxes is exact and far cheaper than
// CGAL's segment-box predicate, and about as selective for the short segments of a grid.
class Candidates {
 public:
  Candidates(const Segment& s, Iterator first, std::vector<Index>& out)
      : box_(s.bbox()), first_(first), out_(out) {}
  bool go_further() const { return true; }
  void intersection(const Segment&, const Primitive& p) {
    out_.push_back(static_cast<Index>(p.id() - first_));
  }
  template <class Node>
  bool do_intersect(const Segment&, const Node& node) const {
    return CGAL::do_overlap(box_, node.bbox());
  }

 private:
  CGAL::Bbox_3 box_;
  Iterator first_;
  std::vector<Index>& out_;
};

// Where segment [a, b] meets triangle t, if it does. The segment's line passes through the
// triangle when the three orientations of (a, b, side) agree; a zero names the side (one)
// or the corner (two) it passes through.
bool classify(const Triangle& t, const Point& a, const Point& b, Index id, SegmentHit& hit) {
  const Point &v0 = t.vertex(0), &v1 = t.vertex(1), &v2 = t.vertex(2);
  const CGAL::Orientation sa = CGAL::orientation(v0, v1, v2, a);
  const CGAL::Orientation sb = CGAL::orientation(v0, v1, v2, b);
  if (sa == sb) {
    if (sa != CGAL::COPLANAR || !CGAL::do_intersect(Segment(a, b), t)) return false;
    hit = {id, 0, 0, true, Feature::face};
    return true;
  }
  const std::array<CGAL::Orientation, 3> e{CGAL::orientation(a, b, v0, v1),
                                           CGAL::orientation(a, b, v1, v2),
                                           CGAL::orientation(a, b, v2, v0)};
  bool positive = false, negative = false;
  int zeros = 0;
  for (int k = 0; k < 3; ++k) {
    positive |= e[k] == CGAL::POSITIVE;
    negative |= e[k] == CGAL::NEGATIVE;
    zeros |= (e[k] == CGAL::COPLANAR) << k;
  }
  if (positive == negative) return false;  // on both sides of the line, or all zero
  // Sides k and k + 1 meet at corner k + 1.
  const Feature feature = zeros == 0   ? Feature::face
                          : zeros == 1 ? edge_feature(0)
                          : zeros == 2 ? edge_feature(1)
                          : zeros == 4 ? edge_feature(2)
                          : zeros == 3 ? vertex_feature(1)
                          : zeros == 6 ? vertex_feature(2)
                                       : vertex_feature(0);
  hit = {id, sign(sa), sign(sb), false, feature};
  return true;
}

// The parameter where segment [a, b] crosses the plane of (v0, v1, v2), in rationals.
double exact_crossing_parameter(const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& a,
                                const Vec3& b) {
  using Q = CGAL::Exact_rational;
  using V = std::array<Q, 3>;
  const auto minus = [](const Vec3& p, const Vec3& q) {
    return V{Q(p.x()) - q.x(), Q(p.y()) - q.y(), Q(p.z()) - q.z()};
  };
  const V e1 = minus(v1, v0), e2 = minus(v2, v0), pa = minus(a, v0), pb = minus(b, v0);
  const V n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
            e1[0] * e2[1] - e1[1] * e2[0]};
  const Q da = n[0] * pa[0] + n[1] * pa[1] + n[2] * pa[2];
  const Q db = n[0] * pb[0] + n[1] * pb[1] + n[2] * pb[2];
  return CGAL::to_double(da / (da - db));
}

// Rays for the winding number: first along the six axes, slightly tilted so that they miss
// the edges of axis-aligned meshes, the one leaving the box soonest first; then, should
// every one of them meet an edge or a corner, 26 more spread over the sphere.
std::vector<Vec3> fallback_directions() {
  std::vector<Vec3> d;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < 26; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / 26.0, r = std::sqrt(1.0 - z * z);
    d.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return d;
}

}  // namespace

struct ExactTree::Impl {
  explicit Impl(const SurfaceGeometry& g) : surfaces(g.num_surfaces()) {
    triangles.reserve(g.triangles.size());
    for (Index t = 0; t < g.num_triangles(); ++t) {
      triangles.emplace_back(point(g.corner(t, 0)), point(g.corner(t, 1)), point(g.corner(t, 2)));
      surface.push_back(g.triangle_surface[t]);
    }
    tree.insert(triangles.begin(), triangles.end());
    tree.build();
    const Box3 b = bounding_box(g);
    lo = b.lo;
    hi = b.hi;
    margin = kRayBeyond * (hi - lo).norm() + 1e-300;
  }

  std::vector<SegmentHit> hits(const Point& a, const Point& b) const {
    std::vector<Index> candidates;
    const Segment segment(a, b);
    Candidates collect(segment, triangles.begin(), candidates);
    tree.traversal(segment, collect);
    std::sort(candidates.begin(), candidates.end());
    std::vector<SegmentHit> out;
    SegmentHit hit;
    for (Index t : candidates)
      if (classify(triangles[t], a, b, t, hit)) out.push_back(hit);
    return out;
  }

  // The winding numbers counted along the ray from p through q, or false if the ray meets
  // a side or a corner beyond p, or runs in a triangle's plane.
  bool count(const Vec3& p, const Vec3& q, std::vector<Containment>& c) const {
    std::fill(c.begin(), c.end(), Containment{});
    for (const SegmentHit& h : hits(point(p), point(q))) {
      Containment& s = c[surface[h.triangle]];
      if (h.coplanar) return false;
      if (h.side_a == 0)
        s.on = true;
      else if (h.feature != Feature::face)
        return false;
      else
        s.winding += h.side_a < 0 ? 1 : -1;  // leaving through the outer side
    }
    return true;
  }

  // The far end of a ray from p along d, beyond the box.
  Vec3 beyond(const Vec3& p, const Vec3& d) const {
    double exit = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k)
      if (d[k] != 0.0) exit = std::min(exit, ((d[k] > 0.0 ? hi[k] : lo[k]) - p[k]) / d[k]);
    return p + (std::max(exit, 0.0) + margin) * d;
  }

  Index surfaces;
  std::vector<Triangle> triangles;
  std::vector<Index> surface;  // per triangle
  Tree tree;
  Vec3 lo, hi;
  double margin;
};

ExactTree::ExactTree(const SurfaceGeometry& geometry)
    : impl_(std::make_unique<const Impl>(geometry)) {}
ExactTree::~ExactTree() = default;

bool segment_hit(const SurfaceGeometry& g, Index t, const Vec3& a, const Vec3& b, SegmentHit& hit) {
  const Triangle triangle(point(g.corner(t, 0)), point(g.corner(t, 1)), point(g.corner(t, 2)));
  return classify(triangle, point(a), point(b), t, hit);
}

std::vector<SegmentHit> ExactTree::hits(const Vec3& a, const Vec3& b) const {
  return impl_->hits(point(a), point(b));
}

std::vector<Containment> ExactTree::containment(const Vec3& p) const {
  std::vector<Containment> c(impl_->surfaces);
  if ((p.array() < impl_->lo.array()).any() || (p.array() > impl_->hi.array()).any()) return c;
  std::array<Vec3, 6> axes;
  for (int k = 0; k < 6; ++k) {
    Vec3 d(0.0, 0.0, 0.0);
    d[k / 2] = k % 2 ? -1.0 : 1.0;
    d[(k / 2 + 1) % 3] = kRayTilt1;
    d[(k / 2 + 2) % 3] = kRayTilt2;
    axes[k] = d;
  }
  std::array<Vec3, 6> ends;
  for (int k = 0; k < 6; ++k) ends[k] = impl_->beyond(p, axes[k]);
  std::array<int, 6> order{0, 1, 2, 3, 4, 5};
  std::sort(order.begin(), order.end(), [&](int x, int y) {
    return (ends[x] - p).squaredNorm() < (ends[y] - p).squaredNorm();
  });
  for (int k : order)
    if (impl_->count(p, ends[k], c)) return c;
  static const std::vector<Vec3> more = fallback_directions();
  for (const Vec3& d : more)
    if (impl_->count(p, impl_->beyond(p, d), c)) return c;
  throw std::logic_error("ExactTree::containment: every ray met an edge");
}

double crossing_parameter(const SurfaceGeometry& geometry, const Vec3& a, const Vec3& b,
                          const SegmentHit& hit) {
  if (hit.side_a == 0) return 0.0;
  if (hit.side_b == 0) return 1.0;
  const Vec3 &v0 = geometry.corner(hit.triangle, 0), &v1 = geometry.corner(hit.triangle, 1),
             &v2 = geometry.corner(hit.triangle, 2);
  const Vec3 n = (v1 - v0).cross(v2 - v0);
  const double da = n.dot(a - v0), db = n.dot(b - v0);
  // Rounding keeps the exact sides' signs unless the segment runs all but parallel to the
  // plane (da and db may then both round to 0, and da / (da - db) to NaN): those are
  // computed again in rationals.
  if (da * hit.side_a > 0.0 && db * hit.side_b > 0.0) return std::clamp(da / (da - db), 0.0, 1.0);
  return std::clamp(exact_crossing_parameter(v0, v1, v2, a, b), 0.0, 1.0);
}

}  // namespace volmesh::surface
