#pragma once
// Back from exact rationals to doubles, checked: each coordinate to its nearest double, then
// every tet's orientation re-tested exactly on the doubles (CGAL's exact predicates). The
// input points round to themselves; a Steiner point may not, and a thin tet can flatten or
// turn over. Such a tet's prism centre (its interior Steiner point) is moved to the mean of
// the rounded corners of the prism's boundary triangles, computed in doubles, when that makes all the prism's tets
// positive; otherwise the mesh is refused (the caller may project along another direction),
// as it is when a face comes out too thin for the validity checker (validity.hpp) to give it
// an area.
#include <string>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/tet/projection.hpp"

namespace volmesh::tet {

struct Rounding {
  Index moved_points = 0;      // Steiner points not representable as doubles, rounded
  Index repaired_prisms = 0;   // prisms whose centre was moved to keep its tets positive
  Index directions_tried = 1;  // projection directions tried before one rounded (the caller's)
};

// The mesh in doubles; boundary faces on the outermost surfaces, tagged by surface (tag s
// names surfaces[s]). Throws InputError naming a tet that rounding flattens or inverts
// beyond repair.
TetMesh round_to_doubles(const ProjectionMesh& mesh,
                         const std::vector<ProjectionSurface>& surfaces, Rounding& rounding);

}  // namespace volmesh::tet
