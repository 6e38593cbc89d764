#pragma once
// Back from exact rationals to doubles, checked: each coordinate to its nearest double, then
// every tet's orientation re-tested exactly on the doubles (CGAL's exact predicates). The
// input points round to themselves; a Steiner point may not, and a thin tet can flatten or
// turn over. Such a tet's prism centre (its interior Steiner point) is first moved to the mean
// of the rounded corners of the prism's boundary triangles when that makes all the prism's
// tets positive; the tets still flat or inverted are then repaired in doubles by the
// improver's local changes (improve/repair.hpp: flips, moving and contracting prism centres),
// the surface points staying where rounding put them. The mesh is refused (the caller may
// project along another direction) only when that leaves a tet that is not positive, or a face
// too thin for the validity checker (validity.hpp) to give it an area.
#include <string>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/improve/slides.hpp"
#include "volmesh/tet/projection.hpp"

namespace volmesh::tet {

struct Rounding {
  Index moved_points = 0;      // Steiner points not representable as doubles, rounded
  Index repaired_prisms = 0;   // prisms whose centre was moved to keep its tets positive
  Index repaired_tets = 0;     // tets still flat or inverted then, removed by local changes
  Index directions_tried = 1;  // projection directions tried before one rounded (the caller's)
};

// The mesh in doubles; boundary faces on the outermost surfaces, tagged by surface (tag s
// names surfaces[s]). Throws InputError naming a tet that rounding flattens or inverts
// beyond repair.
// Points keep the exact mesh's numbers; a surface Steiner point the repair merged into another
// is left with no tet (drop_unused_points() removes them).
TetMesh round_to_doubles(const ProjectionMesh& mesh,
                         const std::vector<ProjectionSurface>& surfaces, Rounding& rounding);

// The mesh without the points no tet uses, the others renumbered in order; returns each old
// point's new number (kNoIndex: dropped).
std::vector<Index> drop_unused_points(TetMesh& mesh);

// Per point of `rounded` (round_to_doubles' numbering), where a surface Steiner point may
// slide: inside the one input triangle its boundary faces lie in, or along the input edge
// of the two; none for the input points and the prism centres.
std::vector<improve::Slide> surface_slides(const ProjectionMesh& exact,
                                           const std::vector<ProjectionSurface>& surfaces,
                                           const TetMesh& rounded);

}  // namespace volmesh::tet
