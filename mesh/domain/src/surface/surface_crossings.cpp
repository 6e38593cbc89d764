// Segment crossings of a surface domain: the triangles the segment meets (exact), merged
// into one event per face interior, edge or vertex; the winding numbers of each piece
// between events follow from the previous piece's across a face, and are found again by a
// ray from the piece's middle after an edge, a vertex, or a piece running in a face.
#include <algorithm>
#include <cstdint>

#include "surface_domain_data.hpp"
#include "volmesh/domain/surface.hpp"

namespace volmesh {

namespace {

using surface::Containment;
using surface::DomainData;
using surface::SegmentHit;
using States = std::vector<Containment>;

// The surface of highest priority (deepest, then highest label) among the hits' for which
// `pick` holds, or kNoIndex.
template <class Pick>
Index deepest(const DomainData& d, const std::vector<const SegmentHit*>& hits, Pick pick) {
  Index best = kNoIndex;
  for (const SegmentHit* h : hits) {
    const Index s = d.geometry.triangle_surface[h->triangle];
    if (pick(s) && (best == kNoIndex || d.depth[s] > d.depth[best] ||
                    (d.depth[s] == d.depth[best] && d.label[s] > d.label[best])))
      best = s;
  }
  return best;
}

// The normal at hits between pieces `before` and `after`: the pseudo-normal of the feature
// met on the deepest surface whose containment changes there (else of the deepest met),
// pointing from `before` into `after`.
Vec3 oriented_normal(const DomainData& d, const std::vector<const SegmentHit*>& hits,
                     const States& before, const States& after) {
  Index s = deepest(d, hits, [&](Index x) { return before[x].inside() != after[x].inside(); });
  if (s == kNoIndex) s = deepest(d, hits, [](Index) { return true; });
  const SegmentHit* h = *std::find_if(hits.begin(), hits.end(), [&](const SegmentHit* x) {
    return d.geometry.triangle_surface[x->triangle] == s;
  });
  const Vec3& n = d.geometry.normal(h->triangle, h->feature);
  return after[s].inside() && !before[s].inside() ? Vec3(-n) : n;
}

}  // namespace

std::vector<Crossing> SurfaceDomain::crossings(const Vec3& a, const Vec3& b) const {
  std::vector<Crossing> out;
  if (!a.allFinite() || !b.allFinite() || a == b) return out;
  const DomainData& d = *data_;
  const std::vector<SegmentHit> hits = d.exact.hits(a, b);
  if (hits.empty()) return out;

  // End points in a triangle's plane (on the surface, or running in a face), and one event
  // per feature met strictly between them, from its lowest triangle.
  const auto [at_a, at_b, events] = surface::segment_events(d.geometry, a, b, hits);

  const auto state_at = [&](double t) { return d.exact.containment(a + t * (b - a)); };
  States left = state_at(0.5 * (events.empty() ? 1.0 : events.front().t));
  if (!at_a.empty()) {
    const States at = d.exact.containment(a);
    if (d.region(at) != d.region(left))
      out.push_back({0.0, a, d.region(at), d.region(left), oriented_normal(d, at_a, at, left)});
  }
  for (std::size_t i = 0; i < events.size();) {
    const double t = events[i].t;
    std::vector<const SegmentHit*> met;
    for (; i < events.size() && events[i].t == t; ++i) met.push_back(events[i].hit);
    const double next = i < events.size() ? events[i].t : 1.0;

    States right = left;
    bool through_faces = true;
    for (const SegmentHit* h : met) {
      const Index s = d.geometry.triangle_surface[h->triangle];
      through_faces &= h->feature == surface::Feature::face && !left[s].on;
      right[s].winding += h->side_a > 0 ? 1 : -1;  // entering through the outer side
    }
    if (!through_faces) right = state_at(0.5 * (t + next));

    // The point itself is on every surface met there.
    States point(left.size());
    for (std::size_t s = 0; s < left.size(); ++s)
      point[s].on = left[s].inside() || right[s].inside();
    for (const SegmentHit* h : met) point[d.geometry.triangle_surface[h->triangle]].on = true;

    const Vec3 x = a + t * (b - a);
    const Index before = d.region(left), after = d.region(right);
    if (before != after)
      out.push_back({t, x, before, after, oriented_normal(d, met, left, right)});
    else if (d.region(point) != before)
      out.push_back({t, x, before, before, oriented_normal(d, met, point, left)});
    left = std::move(right);
  }
  if (!at_b.empty()) {
    const States at = d.exact.containment(b);
    if (d.region(left) != d.region(at))
      out.push_back({1.0, b, d.region(left), d.region(at), oriented_normal(d, at_b, left, at)});
  }
  return out;
}

}  // namespace volmesh
