#pragma once
// The Delaunay interior of a region (FrontOptions::Interior::delaunay): the points of a
// body-centred cubic lattice (cube corners and centres) far enough inside the region, their
// Delaunay tetrahedralisation (CGAL's), and of its tets those of the lattice. The lattice's
// Delaunay tets are congruent (Sommerville's: dihedral angles 60° and 90°), so the core needs
// no quality work; the advancing front fills the layer between it and the region's boundary.
#include <array>
#include <vector>

#include "volmesh/core/progress.hpp"
#include "volmesh/core/types.hpp"

#include "size_field.hpp"

namespace volmesh::tet::front {

// The lattice's cube side over h: 2^(1/6), for which its tet (a twelfth of a cube) has the
// volume of the regular tet of edge h; its edges are then 1.12 h (two) and 0.97 h (four).
inline constexpr double kLatticeStep = 1.122462048309373;
// The least distance of a core point from the region's triangles, over h. Above the lattice
// tet's covering radius (√5/4 of the step, 0.63 h: every point of the tet lies that close to
// one of its corners), so that every core tet lies strictly inside the region; the rest is
// the layer left to the front, at least 0.4 h thick (a core face lies within 0.6 h of a
// corner).
inline constexpr double kCoreClearance = 1.0;

struct Core {
  std::vector<Vec3> points;                  // the core's nodes, in the lattice's order
  std::vector<std::array<Index, 4>> tets;    // positive, into `points`
  // The core's boundary, a closed 2-manifold, each face facing away from the core (out of
  // its tet): the front's convention for the side left to mesh.
  std::vector<std::array<Index, 3>> faces;
};

// The core of the region bounded by `faces` (into `points`; either orientation: inside is
// where an x-ray crosses them an odd number of times) for target edge h. Its tets all lie
// strictly inside the region, their corners at least kCoreClearance·h from every face, and
// tets around an edge or a vertex where its boundary would not be a 2-manifold are dropped.
// Empty when no lattice tet fits. The same for the same input: the lattice is laid over the
// faces' box, the points are inserted in a Hilbert order without randomness and the result
// is ordered by the lattice. With a graded size field (h its cap), only points where the
// field has grown to h are kept, so the front grades from the boundary's size up to the core's.
Core delaunay_core(const std::vector<Vec3>& points,
                   const std::vector<std::array<Index, 3>>& faces, double h,
                   const Progress& progress, const SizeField* field = nullptr);

}  // namespace volmesh::tet::front
