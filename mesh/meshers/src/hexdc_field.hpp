#pragma once
// The signed-distance voxels (positive inside) the hexdc mesher contours, from any Domain.
#include <memory>

#include "volmesh/core/voxel_grid.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/domain/grid_sdf.hpp"
#include "volmesh/domain/surface.hpp"

namespace volmesh::meshers {

// The margin (sdf_layout's fraction of the box's largest side) that leaves at least one node
// of level `level` (2^level nodes per axis) between the domain's box and the grid's border,
// so that the surface never touches the border. Needs level >= 2.
double hexdc_margin(int level);

// The field on a (2^depth + 1)^3 grid:
//  - a signed-distance grid domain (SdfGridDomain) already of that size: its own samples;
//    of another size: its trilinear interpolant on sdf_layout(its bounds, margin);
//  - a surface domain with one outermost surface, on sdf_layout(its bounds, margin): that
//    surface's exact signed distance (SignedDistance; inside it is exactly region != 0);
//  - an analytic domain of one primitive (a ball, a torus, …), on sdf_layout(its bounds,
//    margin): its exact signed distance (closest_surface_point; inside is region != 0);
//  - any other domain, on sdf_layout(its bounds, margin): the sign from region() (inside is
//    region != 0), the magnitude the distance to the nearest boundary crossing along the grid
//    edges at the sample, one spacing where none of them crosses. Along a crossed edge the
//    linear interpolant then vanishes at the exact crossing when it is the nearest one of
//    both ends; elsewhere it is an upper bound of the distance.
// The one outermost surface of a surface domain, or kNoIndex if there are several (disjoint
// solids: their union's distance is not one surface's). Inside the outermost surface is
// exactly region != 0, nested surfaces being interfaces.
Index outermost_surface(const SurfaceDomain& domain);

// The signed distance of a surface domain's one outermost surface, null for any other domain:
// built once, for the field (hexdc_field) and for the projection onto the surface
// (hexdc_surface.hpp), as its tree is the costly part. Throws InputError as SignedDistance does.
std::shared_ptr<const SignedDistance> outer_surface_distance(const Domain& domain);

// `outer` is outer_surface_distance(domain).
VoxelGrid hexdc_field(const Domain& domain, int depth, double margin,
                      const SignedDistance* outer);

}  // namespace volmesh::meshers
