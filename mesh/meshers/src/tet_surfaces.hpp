#pragma once
// The input of the tet meshers that fill triangulated surfaces (tet-projection, tet-front):
// a domain's surfaces, labelled as its regions, checked not to cross.
#include <optional>
#include <string>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/domain/domain.hpp"
#include "volmesh/tet/projection.hpp"

namespace volmesh::meshers {

// The surfaces a tet mesher fills, and whether they were made here (the domain has no
// triangles of its own).
struct BoundarySurfaces {
  std::vector<tet::ProjectionSurface> surfaces;
  bool triangulated = false;
};

// A surface domain's surfaces, the triangulation of a builtin with a polyhedral boundary
// (builtin_surfaces), or else the domain's interfaces triangulated at edge `size`
// (surfacing::mesh_interfaces: analytic domains, domain files, SDF grids, images). A cavity,
// a surface with region 0 inside (the hollow of builtin:thick-sphere), comes with label 0
// and outermost false: the meshers fill it like any region, and drop_cavities removes it.
// Throws InputError naming `method` for a domain that is neither triangulated nor given a size.
BoundarySurfaces triangulated_surfaces(const Domain& domain, const std::string& name,
                                       const std::string& method, std::optional<double> size);

// Throws InputError naming a pair of triangles that intersect (within a surface or across two).
void require_no_intersections(const std::vector<tet::ProjectionSurface>& surfaces,
                              const std::string& name, const std::string& method);

// Removes the tets of region 0 (the cavities' fillings) and the points only they use, and
// makes the faces between the two boundary faces (facing into the cavity).
// A face is tagged by the cavity one of its corners belongs to, `mesh` numbering its points
// as the meshers do (the surfaces' points first, in their order).
void drop_cavities(TetMesh& mesh, const std::vector<tet::ProjectionSurface>& surfaces);

}  // namespace volmesh::meshers
