#include "hexdc_surface.hpp"

#include <memory>

#include "hexdc_field.hpp"
#include "volmesh/domain/grid_sdf.hpp"
#include "volmesh/domain/outer_boundary.hpp"
#include "volmesh/domain/surface.hpp"

namespace volmesh::meshers {

SurfaceProjector hexdc_surface(const Domain& domain) {
  const auto* surfaces = dynamic_cast<const SurfaceDomain*>(&domain);
  const Index outer = surfaces != nullptr ? outermost_surface(*surfaces) : kNoIndex;
  if (outer == kNoIndex) return outer_boundary_map(domain);
  const auto distance =
      std::make_shared<const SignedDistance>(surfaces->surface(outer), "surface");
  return [distance](const Vec3& p) { return distance->closest_point(p); };
}

}  // namespace volmesh::meshers
