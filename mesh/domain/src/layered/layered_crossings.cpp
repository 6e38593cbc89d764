// Segment crossings of a layered domain: the sheet triangles the segment meets (exact), one
// event per face interior, edge or vertex met; the region of every piece between events is
// found exactly at its middle, and the point of an event lies on the sheets met there.
#include <algorithm>
#include <cstdint>

#include "layered_model.hpp"

namespace volmesh::layers {

namespace {

using surface::SegmentHit;
using Hits = std::vector<const SegmentHit*>;

// The normal at hits between a point with sides `before` and one with sides `after`: the
// pseudo-normal of the feature met on a sheet whose side changes there — one that alone
// changes the region if there is one — pointing from before into after.
template <class Before, class After>
Vec3 oriented_normal(const Model& m, const Hits& hits, const Before& before, const After& after,
                     const Vec3& direction) {
  const SegmentHit* pick = nullptr;
  const Index region = m.region(before);
  for (const SegmentHit* h : hits) {
    const Index s = m.geometry.triangle_surface[h->triangle];
    const int b = before(s), a = after(s);
    if (a == b || a == kUnknown || b == kUnknown) continue;
    if (!pick) pick = h;
    if (m.region([&](Index x) { return x == s ? a : before(x); }) != region) {
      pick = h;
      break;
    }
  }
  if (!pick) {  // no side changes (a touch seen from both sides): face the segment
    const Vec3& n = m.geometry.normal(hits.front()->triangle, hits.front()->feature);
    return n.dot(direction) >= 0.0 ? n : Vec3(-n);
  }
  const Index s = m.geometry.triangle_surface[pick->triangle];
  const Vec3& n = m.geometry.normal(pick->triangle, pick->feature);
  return after(s) > before(s) ? n : Vec3(-n);
}

}  // namespace

std::vector<Crossing> crossings(const Model& m, const Vec3& a, const Vec3& b) {
  std::vector<Crossing> out;
  if (!a.allFinite() || !b.allFinite() || a == b) return out;
  const std::vector<SegmentHit> hits = m.hits(a, b);
  if (hits.empty()) return out;  // no sheet met, the box faces included: one region

  const auto [at_a, at_b, events] = surface::segment_events(m.geometry, a, b, hits);

  const Vec3 d = b - a;
  const auto state_at = [&](double t) { return Model::State(m, a + t * d); };
  Model::State left = state_at(0.5 * (events.empty() ? 1.0 : events.front().t));
  if (!at_a.empty()) {
    const Model::State end(m, a);
    const Index at = m.region(end), next = m.region(left);
    if (at != next) out.push_back({0.0, a, at, next, oriented_normal(m, at_a, end, left, d)});
  }
  for (std::size_t i = 0; i < events.size();) {
    const double t = events[i].t;
    Hits met;
    for (; i < events.size() && events[i].t == t; ++i) met.push_back(events[i].hit);
    const Model::State right = state_at(0.5 * (t + (i < events.size() ? events[i].t : 1.0)));
    // The point lies on the sheets met; elsewhere it is where both pieces are.
    const auto point = [&](Index s) {
      for (const SegmentHit* h : met)
        if (m.geometry.triangle_surface[h->triangle] == s) return 0;
      const int l = left(s), r = right(s);
      return l == r ? l : l == kUnknown ? r : r == kUnknown ? l : 0;
    };
    const Vec3 x = a + t * d;
    const Index before = m.region(left), after = m.region(right);
    if (before != after)
      out.push_back({t, x, before, after, oriented_normal(m, met, left, right, d)});
    else if (m.region(point) != before)
      out.push_back({t, x, before, before, oriented_normal(m, met, left, point, d)});
    left = right;
  }
  if (!at_b.empty()) {
    const Model::State end(m, b);
    const Index last = m.region(left), at = m.region(end);
    if (last != at) out.push_back({1.0, b, last, at, oriented_normal(m, at_b, left, end, d)});
  }
  return out;
}

}  // namespace volmesh::layers
