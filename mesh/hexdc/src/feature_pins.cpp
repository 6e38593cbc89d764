// The optimiser's pinned feature nodes (feature_pins.hpp).
#include "feature_pins.hpp"

#include "polyline.hpp"

namespace volmesh::hexdc_detail {

FeaturePins feature_pins(std::size_t nodes, const SurfaceFeatures* features,
                         const FeatureLayer* layer) {
  FeaturePins pins;
  if (features == nullptr || layer == nullptr || layer->pinned.empty()) return pins;
  pins.features = features;
  pins.crease.assign(nodes, kNotPinned);
  pins.corner.assign(nodes, Vec3::Zero());
  for (const PinnedNode& pin : layer->pinned)
    if (pin.corner) {
      pins.crease[static_cast<std::size_t>(pin.node)] = kCornerPin;
      pins.corner[static_cast<std::size_t>(pin.node)] = pin.target;
    }
  for (const FeatureChain& chain : layer->chains)
    for (const Index v : chain.nodes)
      if (pins.crease[static_cast<std::size_t>(v)] == kNotPinned)
        pins.crease[static_cast<std::size_t>(v)] = chain.crease;
  return pins;
}

Vec3 pinned_point(const FeaturePins& pins, std::size_t v, const Vec3& x) {
  if (pins.crease[v] == kCornerPin) return pins.corner[v];
  return closest_on_polyline(x, pins.features->creases[static_cast<std::size_t>(pins.crease[v])]);
}

Vec3 pinned_direction(const FeaturePins& pins, std::size_t v, const Vec3& x) {
  return polyline_tangent(x, pins.features->creases[static_cast<std::size_t>(pins.crease[v])]);
}

}  // namespace volmesh::hexdc_detail
