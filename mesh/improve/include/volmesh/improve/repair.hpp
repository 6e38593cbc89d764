#pragma once
// Repair of a tet mesh whose coordinates were perturbed (rounded from exact numbers, say) so
// that some tets came out flat or inverted: the improver's operations, each checked by the
// exact orientation test on the doubles as they stand, remove those tets.
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/improve/slides.hpp"

namespace volmesh::improve {

struct RepairStats {
  Index bad_before = 0, bad_after = 0;  // tets not positive by the exact test
  long long smoothed = 0;               // free points moved
  long long flips = 0;                  // edge and face removals
  long long contractions = 0;
};

// Removes the mesh's flat and inverted tets where it can: for each, the topological changes
// around it (edge removal, multi-face removal), then moving its free corners (optimisation-
// based smoothing towards where their whole star is positive), then contracting its edges
// into a neighbour. A change is kept when every new tet is positive by the exact test and the
// worst quality it touches rises, so the positive tets stay positive. Boundary and interface
// faces stay, their corners fixed, except that a point `slides` lets slide in a triangle or
// along an edge of the surface may merge into a point of that triangle or edge (the surface
// then split by fewer points). Every point keeps its number; one contracted away is left with
// no tet. bad_after > 0 says what is left; serial, so deterministic.
RepairStats repair_flat_tets(TetMesh& mesh, const std::vector<Slide>& slides = {});

}  // namespace volmesh::improve
