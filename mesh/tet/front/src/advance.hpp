#pragma once
// The advancing front in one region: from its boundary triangles (facing into it) to tets,
// until the front is empty or stalls.
#include <array>
#include <vector>

#include "size_field.hpp"
#include "volmesh/core/progress.hpp"
#include "volmesh/core/types.hpp"
#include "volmesh/tet_front/front.hpp"

namespace volmesh::tet::front {

// The paper's constants, for target edge h (the local size at the face or node).
inline constexpr double kSolidAngleRadius = 1.4142135623730951;  // √2 h: the ball counted
inline constexpr double kCandidateRadius = 1.7320508075688772;   // √3 h: fourth corners sought
inline constexpr double kMaxVolume = 0.15;                       // Vmax = 0.15 h^3
inline constexpr double kShrink = 0.75;                          // H := 0.75 H
inline constexpr double kFreeBallRadius = 2.0;                   // 2 h / n about a new node

struct RegionFront {
  std::vector<std::array<Index, 4>> tets;    // positive
  std::vector<std::array<Index, 3>> cavity;  // the front left when it stalled, facing in
  long long new_nodes = 0, existing_node_tets = 0, relaxed_tets = 0, aux_points = 0, aux_deleted = 0;
};

// Appends the new nodes to `points`. `faces` bound the region, each facing into it
// (det(b - a, c - a, p - a) > 0 for p inside near the face); h is field's local size.
RegionFront advance_front(std::vector<Vec3>& points, const std::vector<std::array<Index, 3>>& faces,
                          const FrontOptions& options, const SizeField& field,
                          const Progress& progress);

}  // namespace volmesh::tet::front
