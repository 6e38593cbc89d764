#pragma once
// A triangulated surface: the input of surface domains and of the signed-distance tool.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh {

struct TriSurface {
  std::vector<Vec3> points;
  std::vector<std::array<Index, 3>> triangles;
  Index num_points() const { return static_cast<Index>(points.size()); }
  Index num_triangles() const { return static_cast<Index>(triangles.size()); }
};

// "vertex index 90 out of range (82 vertices)": how readers and checks word a bad corner.
std::string vertex_index_error(std::int64_t index, Index num_points);

// Throws InputError "SOURCE: triangle T: vertex index ..." for the first triangle with a
// corner that is not a point of the surface. Writers and checks call it first.
void require_valid_indices(const TriSurface& surface, const std::string& source);

}  // namespace volmesh
