#pragma once
// Tetrahedra of size h by advancing front with an auxiliary point array (docs/methods.md,
// "tet-front"): fills closed, outward, non-self-intersecting triangulated surfaces with tets
// of target edge h, keeping the surface triangles (a fallback cut may split one: counted).
//
// h is local (graded): near the boundary the boundary triangles' mean edge, growing inward by
// a quarter of the distance up to the target size (FrontOptions::size, or interior_size).
//
// Each region (the inside of its surfaces, outside the ones nested in it) is meshed on its own:
//  - auxiliary points at step h/n (an octree of cells about h wide, n^3 points each), one bit
//    each, alive inside the region;
//  - the front starts as the region's boundary triangles, facing into the region;
//  - the front node with the fewest live auxiliary points within √2·h (the smallest solid
//    angle) is taken, then its front face with the least sum over its corners;
//  - the fourth corner is the best existing front node within √3·h of the face's corners, or
//    else a new node at the face's barycentre + H along its normal, H = min(3 Vmax / S, √S)
//    shrunk by 0.75 until it fits, in a ball of radius 2h/n free of deleted points;
//  - a tet is refused if it holds a deleted auxiliary point strictly inside, a front node, is
//    crossed by a front edge or crosses a front face (exact predicates), is not positive,
//    exceeds Vmax = 0.15 h^3, or leaves a gap flatter than a sine of 1e-6 against a front face
//    at a shared corner (a shape rule); the best by volume / (largest product of the three
//    edges at a corner) is kept; the auxiliary points it covers are deleted and the front
//    updated.
// When no face of the front can advance (a stall), the rest of the region is closed (counted in
// the stats): one tet, a fan from a point that sees the whole cavity, or the projection mesher's
// tets, merged even where they cut the cavity's faces by refining the tets outside to match;
// with no projection direction whose tets all stay positive, InputError names the cavity.
// Last, the mesh improver (volmesh/improve) raises its worst tets, the input triangles and the
// surfaces between regions kept (the fallback's points inside outer input triangles or on
// their edges may slide within them).
// With FrontOptions::Interior::delaunay, each region first gets a core: the Delaunay tets of a
// body-centred cubic lattice of edge about h at least h inside it (congruent tets, dihedral
// angles 60° and 90°); the front starts from the region's triangles and the core's boundary,
// and meshes only the layer between them.
#include <string>
#include <utility>
#include <vector>

#include "volmesh/core/element_mesh.hpp"
#include "volmesh/core/progress.hpp"
#include "volmesh/improve/improve.hpp"
#include "volmesh/tet/projection.hpp"

namespace volmesh::tet {

inline constexpr int kDefaultAuxRatio = 12;

// How each region's inside is filled: a Delaunay core and the front in the layer around it,
// or the front throughout.
enum class Interior { delaunay, front };

struct FrontOptions {
  double size = 0.0;                // h, the target edge
  int aux_ratio = kDefaultAuxRatio;  // n: auxiliary points at h / n
  // A test hook: the front stops after this many tets per region, as if it stalled (-1: never).
  long long stop_after = -1;
  bool improve = true;  // improve the finished mesh (volmesh/improve/improve.hpp)
  Interior interior = Interior::front;
  // Graded sizes: the size grows inward from the boundary's up to this (0: up to `size`).
  double interior_size = 0.0;
};

struct FrontStats {
  long long tets = 0, nodes = 0;
  long long core_points = 0, core_tets = 0;  // the Delaunay interior's (Interior::delaunay)
  long long front_tets = 0;     // made by the advancing front
  long long new_nodes = 0;      // placed by the front (beyond the surface points)
  long long existing_node_tets = 0;  // tets whose fourth corner was already a front node
  // Of those, tets that passed the exact tests only (beyond Vmax or over deleted auxiliary
  // points), tried before a face counts as failed.
  long long relaxed_tets = 0;
  // Live inside the regions (outside their cores) at the start; deleted.
  long long aux_points = 0, aux_deleted = 0;
  long long stalls = 0;         // regions whose front could not advance further
  long long fallback_tets = 0;  // tets that close the stalled cavities
  long long cavity_faces = 0;   // front faces left by the stalls
  long long largest_cavity = 0;  // faces of the largest stalled cavity
  // Where the projection mesh of a cavity cuts its faces, the tets outside holding a cut face
  // or edge are coned from their centroids: the cavity faces cut, the tets refined, the input
  // boundary triangles cut (the enclosed volume is unchanged), and the points the fallback
  // added (projection Steiner points, fan apexes, centroids).
  long long split_cavity_faces = 0;
  long long refined_tets = 0;
  long long split_boundary_faces = 0;
  long long steiner_points = 0;
  ::volmesh::improve::ImproveStats improve;  // the last pass (empty when FrontOptions::improve is off)
  // The local size h(x) (graded from the boundary triangles): its least and largest values
  // and its growth per unit distance from the boundary (0 when uniform).
  double size_min = 0.0, size_max = 0.0, grading_rate = 0.0;
  // Seconds by stage: interior, front, fallback.
  std::vector<std::pair<std::string, double>> seconds;
};

struct FrontResult {
  // Points: the surfaces' points in their order, then the new nodes (with Interior::delaunay,
  // each region's core points before its front's). Boundary faces: the outermost surfaces'
  // triangles, tagged by surface.
  TetMesh mesh;
  FrontStats stats;
};

// Refuses (InputError "tet-front: <name>: --size <h> ...", naming the limit) a size h that is
// not a positive finite length, exceeds the diagonal of the boundary's box [lo, hi] (it could
// not mesh anything finer than that box), or is too small: its auxiliary grid at h / aux_ratio
// would not fit in the memory set aside for it (the message gives the smallest size allowed).
void require_front_size(const std::string& name, double h, int aux_ratio, const Vec3& lo,
                        const Vec3& hi);

// Refuses (InputError "tet-front: <name>: --interior-size <H> ...") an interior size that is not
// a positive finite length, is below the size h, or exceeds the diagonal of the box [lo, hi].
void require_front_interior_size(const std::string& name, double interior, double h,
                                 const Vec3& lo, const Vec3& hi);

// Throws InputError as require_front_size and require_front_interior_size do, when the
// graded auxiliary points would not fit in their memory, or when no direction closes a
// stalled cavity.
FrontResult tetrahedralize_by_front(const std::vector<ProjectionSurface>& surfaces,
                                    const FrontOptions& options, const Progress& progress = {});

}  // namespace volmesh::tet
