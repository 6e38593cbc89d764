#pragma once
// The input of the tet meshers that fill triangulated surfaces (tet-projection, tet-front):
// a domain's surfaces, labelled as its regions, checked not to cross.
#include <string>
#include <vector>

#include "volmesh/domain/domain.hpp"
#include "volmesh/tet/projection.hpp"

namespace volmesh::meshers {

// A surface domain's surfaces, or the triangulation of a builtin with a polyhedral boundary
// (builtin_surfaces). Throws InputError naming `method` for a domain given otherwise.
std::vector<tet::ProjectionSurface> triangulated_surfaces(const Domain& domain,
                                                          const std::string& name,
                                                          const std::string& method);

// Throws InputError naming a pair of triangles that intersect (within a surface or across two).
void require_no_intersections(const std::vector<tet::ProjectionSurface>& surfaces,
                              const std::string& name, const std::string& method);

}  // namespace volmesh::meshers
