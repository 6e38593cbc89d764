// The events of a segment through a triangulated surface, shared by the surface and layered
// domains' crossings.
#include <algorithm>

#include "surface_exact.hpp"

namespace volmesh::surface {

namespace {

std::uint64_t feature_key(const SurfaceGeometry& g, const SegmentHit& h) {
  const int f = static_cast<int>(h.feature);
  const auto& corners = g.triangles[h.triangle];
  if (f == 0) return static_cast<std::uint64_t>(h.triangle);
  if (f >= 4) return std::uint64_t{2} << 62 | static_cast<std::uint64_t>(corners[f - 4]);
  const std::uint64_t x = corners[f - 1], y = corners[f % 3];
  return std::uint64_t{1} << 62 | std::min(x, y) << 31 | std::max(x, y);
}

}  // namespace

SegmentEvents segment_events(const SurfaceGeometry& geometry, const Vec3& a, const Vec3& b,
                             const std::vector<SegmentHit>& hits) {
  SegmentEvents out;
  auto& events = out.events;
  for (const SegmentHit& h : hits) {
    if (h.side_a == 0) out.at_a.push_back(&h);
    if (h.side_b == 0) out.at_b.push_back(&h);
    if (h.side_a != 0 && h.side_b != 0)
      events.push_back({crossing_parameter(geometry, a, b, h), feature_key(geometry, h), &h});
  }
  const auto by_key = [](const SegmentEvent& x, const SegmentEvent& y) { return x.key < y.key; };
  std::stable_sort(events.begin(), events.end(), by_key);
  events.erase(std::unique(events.begin(), events.end(),
                           [](const SegmentEvent& x, const SegmentEvent& y) { return x.key == y.key; }),
               events.end());
  std::sort(events.begin(), events.end(), [](const SegmentEvent& x, const SegmentEvent& y) {
    return x.t != y.t ? x.t < y.t : x.key < y.key;
  });
  return out;
}

}  // namespace volmesh::surface
