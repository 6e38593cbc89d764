#include "volmesh/core/tri_surface.hpp"

#include "volmesh/core/errors.hpp"

namespace volmesh {

std::string vertex_index_error(std::int64_t index, Index num_points) {
  return "vertex index " + std::to_string(index) + " out of range (" + std::to_string(num_points) +
         " vertices)";
}

void require_valid_indices(const TriSurface& surface, const std::string& source) {
  const Index n = surface.num_points();
  for (std::size_t t = 0; t < surface.triangles.size(); ++t)
    for (Index v : surface.triangles[t])
      if (v < 0 || v >= n)
        throw InputError(source + ": triangle " + std::to_string(t) + ": " +
                         vertex_index_error(v, n));
}

}  // namespace volmesh
