// Segment crossings of an analytic domain: every primitive's line events on the segment,
// merged in order; between consecutive events each primitive is in, out or on (the segment
// runs in its surface), so every open piece has a region, and an event is a crossing where
// the region changes, or where the point itself gets another region (a tangential touch).
#include <algorithm>
#include <array>
#include <cmath>

#include "analytic_shapes.hpp"

namespace volmesh {
namespace analytic {

LineHits line_hits(const Primitive& prim, const Vec3& al, const Vec3& bl) {
  LineHits h = std::visit([&](const auto& s) { return line_hits(s, al, bl - al); }, prim.shape);
  for (int k = 0; k < h.count; ++k) h.events[k].normal = prim.frame.rotation * h.events[k].normal;
  return h;
}

}  // namespace analytic

namespace {

using analytic::LineHits;
using analytic::Side;
using Mask = AnalyticDomain::Mask;

// Largest parameter distance by which a root may be moved onto an end point of the segment.
constexpr double kSnap = 1e-8;
static_assert(kSnap < analytic::kSearchMargin, "roots to snap must be searched for");

// The primitive's side on the open piece just after t_end = 0, or just before t_end = 1.
Side side_next_to(const LineHits& h, double t_end) {
  Side s = h.start;
  for (int k = 0; k < h.count; ++k)
    if (t_end == 0.0 ? h.events[k].t <= 0.0 : h.events[k].t < 1.0) s = h.events[k].after;
  return s;
}

// An end point on the surface is a root of the line equation, and an end point within
// rounding of the surface may be classified differently from the roots next to it. In both
// cases the nearest root is moved onto the end point, so that the end point's own side
// decides and rounding never adds a spurious pair of crossings there.
void snap(LineHits& h, Side at_end, double t_end) {
  int nearest = -1;
  for (int k = 0; k < h.count; ++k)
    if (nearest < 0 || std::abs(h.events[k].t - t_end) < std::abs(h.events[nearest].t - t_end))
      nearest = k;
  if (nearest < 0 || std::abs(h.events[nearest].t - t_end) > kSnap) return;
  const Side next = side_next_to(h, t_end);
  if (at_end == Side::on || (next != Side::on && next != at_end)) h.events[nearest].t = t_end;
}

struct Event {
  double t;
  int primitive;
  Side after;
  Vec3 normal;  // outward, world
};

void set_side(Mask& in, Mask& on, int i, Side s) {
  const Mask bit = Mask{1} << i;
  in = s == Side::in ? in | bit : in & ~bit;
  on = s == Side::on ? on | bit : on & ~bit;
}

}  // namespace

std::vector<Crossing> AnalyticDomain::crossings(const Vec3& a, const Vec3& b) const {
  std::vector<Crossing> out;
  if (!a.allFinite() || !b.allFinite() || a == b) return out;

  std::array<Event, kMaxPrimitives * 4> events;
  int count = 0;
  Masks at_a, at_b, piece;  // the end points, and the open piece after a
  for (std::size_t i = 0; i < primitives_.size(); ++i) {
    if (analytic::apart(reach_[i], a, b)) continue;  // outside it all along
    const Primitive& prim = primitives_[i];
    const int pi = static_cast<int>(i);
    const Vec3 al = analytic::to_local(prim.frame, a), bl = analytic::to_local(prim.frame, b);
    const Side side_a = analytic::classify_local(prim.shape, al);
    const Side side_b = analytic::classify_local(prim.shape, bl);
    set_side(at_a.in, at_a.on, pi, side_a);
    set_side(at_b.in, at_b.on, pi, side_b);
    LineHits h = analytic::line_hits(prim, al, bl);
    snap(h, side_a, 0.0);
    snap(h, side_b, 1.0);
    Side start = h.start;
    for (int k = 0; k < h.count; ++k) {
      const analytic::LineEvent& e = h.events[k];
      if (e.t <= 0.0)
        start = e.after;
      else if (e.t < 1.0)
        events[count++] = {e.t, pi, e.after, e.normal};
    }
    set_side(piece.in, piece.on, pi, start);
  }
  std::sort(events.begin(), events.begin() + count, [](const Event& x, const Event& y) {
    return x.t != y.t ? x.t < y.t : x.primitive < y.primitive;
  });

  // The normal of the lowest primitive among `candidates` (surfaces through the point),
  // oriented into the side given by mask `into`.
  const auto oriented = [](Mask candidates, Mask into, auto&& normal_of) {
    int i = 0;
    while (!(candidates >> i & 1)) ++i;
    const Vec3 n = normal_of(i);
    return (into >> i & 1) ? Vec3(-n) : n;
  };
  const auto gradient_at = [&](const Vec3& p) {
    return [&, p](int i) {
      const Primitive& prim = primitives_[i];
      return Vec3(prim.frame.rotation *
                  analytic::gradient(prim.shape, analytic::to_local(prim.frame, p)));
    };
  };

  // The piece after t reaches the next event; its midpoint decides between coincident
  // surfaces the segment runs in (winner() only looks when it does).
  const auto piece_point = [&](double t, int next) {
    return Vec3(a + 0.5 * (t + (next < count ? events[next].t : 1.0)) * (b - a));
  };
  Mask left = winner(piece, piece_point(0.0, 0));
  if (const Mask w = winner(at_a, a); table_[w] != table_[left])
    out.push_back({0.0, a, table_[w], table_[left], oriented(w ^ left, left, gradient_at(a))});
  for (int g = 0; g < count;) {
    // The events at this exact t; primitives without one keep their side across it.
    const double t = events[g].t;
    const int first = g;
    Mask crossed = 0;
    Masks after = piece;
    for (; g < count && events[g].t == t; ++g) {
      crossed |= Mask{1} << events[g].primitive;
      set_side(after.in, after.on, events[g].primitive, events[g].after);
    }
    const Vec3 point = a + t * (b - a);
    const Mask right = winner(after, piece_point(t, g));
    const Mask at = winner({piece.in & ~crossed, piece.on | crossed}, point);
    const auto event_normal = [&](int i) {
      int k = first;
      while (events[k].primitive != i) ++k;
      return events[k].normal;
    };
    if (table_[left] != table_[right]) {
      const Mask c = (left ^ right) & crossed;
      out.push_back({t, point, table_[left], table_[right],
                     oriented(c != 0 ? c : crossed, right, event_normal)});
    } else if (table_[at] != table_[left]) {
      // A touch: the normal points out of the region of the touching point.
      const Mask c = (at ^ left) & crossed;
      out.push_back({t, point, table_[left], table_[left],
                     oriented(c != 0 ? c : crossed, left, event_normal)});
    }
    piece = after;
    left = right;
  }
  if (const Mask w = winner(at_b, b); table_[w] != table_[left])
    out.push_back({1.0, b, table_[left], table_[w], oriented(left ^ w, w, gradient_at(b))});
  return out;
}

}  // namespace volmesh
