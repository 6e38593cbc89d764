#include "volmesh/runs/mesh_input.hpp"

#include <limits>

#include "volmesh/core/errors.hpp"
#include "volmesh/io/mesh_io.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh::cli {

void require_known_format(const std::filesystem::path& path) {
  if (!is_surface_file(path) && !is_mesh_file(path))
    throw InputError(path.string() +
                     ": unknown format (surfaces: .stl .off .obj .ply; meshes: .vtu .msh .mesh .node .ele)");
}

Box bounding_box(const std::vector<Vec3>& points) {
  Box b{Vec3::Constant(std::numeric_limits<double>::infinity()),
        Vec3::Constant(-std::numeric_limits<double>::infinity())};
  for (const Vec3& p : points) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  if (points.empty()) b.lo = b.hi = Vec3::Zero();
  return b;
}

}  // namespace volmesh::cli
