#pragma once
// The surface the hexdc mesher projects its boundary nodes onto (project.hpp): the domain's
// TRUE boundary, the one the solver evaluates boundary data on.
#include <memory>

#include "volmesh/domain/domain.hpp"
#include "volmesh/domain/grid_sdf.hpp"
#include "volmesh/hexdc/project.hpp"

namespace volmesh::meshers {

// The closest point of the domain's outer boundary:
//  - a surface domain with one outermost surface: the closest point of its triangles by
//    `outer`, outer_surface_distance(domain) (exact up to rounding), as its field is that
//    surface's signed distance (hexdc_field.hpp);
//  - any other domain: outer_boundary_map (volmesh/domain/outer_boundary.hpp), as the solver's
//    true_boundary_map: exact per primitive for analytic solids; for a signed-distance grid the
//    zero set of its trilinear interpolant, found along the gradient line through the point.
// The projector refers to `domain`, which must outlive it.
SurfaceProjector hexdc_surface(const Domain& domain,
                               std::shared_ptr<const SignedDistance> outer);

}  // namespace volmesh::meshers
