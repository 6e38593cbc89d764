#pragma once
// The surface a hex mesh's boundary nodes belong on, as its closest-point map (project.hpp,
// untangle.hpp).
#include <functional>

#include "volmesh/core/types.hpp"

namespace volmesh {

// The closest point of the surface to a point.
using SurfaceProjector = std::function<Vec3(const Vec3&)>;

}  // namespace volmesh
