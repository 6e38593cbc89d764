#include "hexdc_surface.hpp"

#include <memory>
#include <utility>

#include "volmesh/domain/outer_boundary.hpp"

namespace volmesh::meshers {

SurfaceProjector hexdc_surface(const Domain& domain,
                               std::shared_ptr<const SignedDistance> outer) {
  if (outer == nullptr) return outer_boundary_map(domain);
  return [outer = std::move(outer)](const Vec3& p) { return outer->closest_point(p); };
}

}  // namespace volmesh::meshers
