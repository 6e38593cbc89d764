#pragma once
// A triangulated surface: the input of surface domains, the SDF tool and the tet meshers.
#include <array>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh {

struct TriSurface {
  std::vector<Vec3> points;
  std::vector<std::array<Index, 3>> triangles;
  Index num_points() const { return static_cast<Index>(points.size()); }
  Index num_triangles() const { return static_cast<Index>(triangles.size()); }
};

}  // namespace volmesh
