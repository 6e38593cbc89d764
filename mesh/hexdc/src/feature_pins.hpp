#pragma once
// The buffer layer's feature nodes as the optimiser keeps them (optimise.hpp): each chain node
// on its crease's polyline, each corner node on its corner.
#include <cstddef>
#include <vector>

#include "volmesh/hexdc/feature_layer.hpp"
#include "volmesh/hexdc/features.hpp"

namespace volmesh::hexdc_detail {

// FeaturePins::crease of a node kept nowhere, and of a corner node.
inline constexpr Index kNotPinned = -1;
inline constexpr Index kCornerPin = -2;

struct FeaturePins {
  const SurfaceFeatures* features = nullptr;
  // Per mesh node: the crease (in features->creases) it is kept on, kNotPinned or kCornerPin.
  std::vector<Index> crease;
  std::vector<Vec3> corner;  // per mesh node: a corner node's point
};

// The pins of `layer`'s chains and corner nodes on `features`, for a mesh of `nodes` nodes; a
// node on two chains stays on the first one's crease. No pins without either or without a
// pinned node (the optimiser then finds creases from the normals).
FeaturePins feature_pins(std::size_t nodes, const SurfaceFeatures* features,
                         const FeatureLayer* layer);

inline bool pinned(const FeaturePins& pins, std::size_t v) {
  return !pins.crease.empty() && pins.crease[v] != kNotPinned;
}

// Where pinned node v at x belongs: its corner, or the closest point of its crease.
Vec3 pinned_point(const FeaturePins& pins, std::size_t v, const Vec3& x);

// The direction pinned crease node v at x may slide in: its crease's tangent at the closest point.
Vec3 pinned_direction(const FeaturePins& pins, std::size_t v, const Vec3& x);

}  // namespace volmesh::hexdc_detail
