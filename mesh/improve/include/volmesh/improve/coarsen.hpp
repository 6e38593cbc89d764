#pragma once
// Coarsening by edge contraction, for meshes with far more points than their boundary needs
// (the projection mesher's): interior points first, then boundary points that `slides` lets
// slide within a triangle or along an edge of the surface, each merged into a neighbour
// that stays where it is (for a boundary point, one in the closure of its triangle or edge,
// so that the surface stays the same point set, split by fewer points). A contraction is kept
// when every new tet is positive by the exact test, the mesh stays a manifold with the same
// boundary, and the new tets' worst quality is at least the floor, or at least the worst of
// the tets they replace when those were already below it: the aim is the count, and the
// improver (improve.hpp) raises the quality afterwards.
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/progress.hpp"
#include "volmesh/improve/slides.hpp"

namespace volmesh::improve {

// The default floor: a smallest dihedral sine of 0.1 (an angle of about 5.7°).
inline constexpr double kDefaultCoarsenFloor = 0.1;

struct CoarsenOptions {
  double quality_floor = kDefaultCoarsenFloor;
  // Per point, where it may slide (slides.hpp); empty: only interior points go.
  std::vector<Slide> slides;
  Progress progress;
};

struct CoarsenStats {
  Index points_before = 0, points_after = 0, tets_before = 0, tets_after = 0;
  long long interior = 0, boundary = 0;  // contractions of each kind
  int passes = 0;
};

// Coarsens `mesh` in place: points removed (the others keep their order), tets renumbered,
// regions kept, boundary faces renamed where a boundary point went (tags kept). Throws
// InputError when a tet of the input is not positive by the exact test. Serial, so the result
// is the same for any thread count.
CoarsenStats coarsen_tet_mesh(TetMesh& mesh, const CoarsenOptions& options = {});

}  // namespace volmesh::improve
