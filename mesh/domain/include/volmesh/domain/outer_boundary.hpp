#pragma once
// The closest point of a domain's outer boundary (the interfaces with region 0): where the
// solver evaluates boundary data (the TRUE boundary) and where meshers put boundary nodes.
#include <functional>

#include "volmesh/domain/domain.hpp"

namespace volmesh {

// The closest point of the domain's outer boundary. For an AnalyticDomain it is exact: each
// primitive's own closest point (sphere: radial projection; box, cylinder, half-space:
// clamping; torus: closed form; ellipsoid: Eberly's root bracketing), keeping those that lie
// on the outer boundary or on its edges, the nearest of them. Any other domain, or a point
// for which no primitive's closest point lies on the boundary, uses project_along_normals.
// The map refers to `domain`, which must outlive it.
std::function<Vec3(const Vec3&)> outer_boundary_map(const Domain& domain);

// Closest-point iteration with the domain's own queries: q ← the outer-boundary crossing
// nearest to p on the line through p along normal(q), starting from normal(p). A fixed point
// is a point whose normal line passes through p: a closest point. The error shrinks by about
// (distance × curvature) per step, so for mesh points O(h) from a smooth surface a few steps
// reach rounding; it stops when a step moves q by less than 1e-14 of the domain size (at
// most 50 steps). The result lies on the surface as accurately as Domain::crossings puts it
// (1e-12 for analytic solids) and is the closest point as accurately as Domain::normal is
// (exact for analytic solids; for a triangulated surface, whose normals are per triangle, it
// is the closest point of the triangulation). Returns p when no boundary is found within
// the domain's bounding box diagonal.
Vec3 project_along_normals(const Domain& domain, const Vec3& p);

}  // namespace volmesh
