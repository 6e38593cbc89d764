#pragma once
// The interfaces of any Domain (analytic, CSG, SDF grid, image) as closed triangulated
// surfaces of edge about h, for the meshers that fill triangulated surfaces (tet-front,
// tet-projection).
//
// CGAL's Mesh_3 Delaunay refinement restricted to the surface (Labeled_mesh_domain_3 over
// Domain::region, facet criteria only, no cell criteria, sequential, no optimisers): the
// surface Delaunay balls have radius at most about h / √3 and the facets angles of at least
// 30°, and the manifold option makes the restricted facets a closed 2-manifold. Vertices
// lie on the interfaces up to the bisection bound (kRelativeError of the bounds' diagonal).
// The refinement starts from the interface crossings of a few lines through the bounds
// (Domain::crossings), so that every surface those lines meet is found (CGAL's default
// shoots rays from the bounds' centre, which see only the innermost of nested surfaces).
// Deterministic: the same domain and h give the same surfaces, in the same order.
#include <vector>

#include "volmesh/core/tri_surface.hpp"
#include "volmesh/core/types.hpp"
#include "volmesh/domain/domain.hpp"

namespace volmesh::surfacing {

inline constexpr double kRelativeError = 1e-12;

// One connected component of the interfaces: oriented out of `inside`, enclosing a positive
// volume; `outside` is the region around it (0 for the outer boundary).
struct InterfaceSurface {
  TriSurface surface;
  Index inside = 0;   // 0 for a cavity (the hollow of builtin:thick-sphere)
  Index outside = 0;
};

// Throws InputError if h is not positive and finite, if h is too small for the bounds (more
// than kMaxFacets triangles expected) or if no interface is found.
std::vector<InterfaceSurface> mesh_interfaces(const Domain& domain, double h);

}  // namespace volmesh::surfacing
