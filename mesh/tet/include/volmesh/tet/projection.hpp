#pragma once
// Tetrahedralization by projection (docs/methods.md, "tet-projection"): fills any set of closed,
// outward, non-self-intersecting, mutually non-crossing triangulated surfaces with tetrahedra in
// exact rationals; rounding to doubles (rounding.hpp) can flatten a tet, and is then refused.
//
// The stages, along the projection axis (z after a cyclic permutation of the coordinates):
//  1. classify: each triangle is TOP (outward normal up), BOT (down) or WALL (vertical), by
//     the exact orientation of its projection;
//  2. project: every projected edge of every triangle is a constraint of one constrained
//     Delaunay triangulation of the plane (exact intersections): the LAYs of all TOP
//     triangles in one, so that the prisms meet face to face across the plane;
//  3. prisms: above each plane triangle the triangles covering it (found in a 2D grid cache)
//     are sorted by height; each gap between consecutive ones inside the domain is a prism
//     (a bottom and a top triangle over the plane triangle, degenerate down to a tet);
//  4. stitch: over each plane edge the surface lines (and WALL triangles) cut the vertical
//     strip into bands; every band is triangulated once, canonically, with every surface
//     point found on its two vertical sides, so both prisms beside a side face triangulate
//     it identically;
//  5. fill: each prism becomes the tets joining its centre (the mean of its six corners) to
//     its boundary triangles.
#include <array>
#include <gmpxx.h>
#include <string>
#include <vector>

#include "volmesh/core/progress.hpp"
#include "volmesh/core/tri_surface.hpp"
#include "volmesh/core/types.hpp"

namespace volmesh::tet {

enum class Axis { x, y, z };

struct ProjectionSurface {
  TriSurface surface;  // closed, manifold, oriented outward
  Index label = 1;     // the region inside it and outside the surfaces nested in it
  bool outermost = true;  // inside no other surface
  std::string name = "surface";
};

// The oblique directions a projection may take besides the axes: tilt k (1 to kTilts) projects
// along (-a, -b, 1) in the axis's frame, (a, b) = kTilt[k - 1], by the exact shear
// (x + a z, y + b z, z). Dyadic, so sheared doubles stay short rationals; generic, so that
// points and edges of a symmetric model that meet in projection only up to rounding (a
// rotated cube's corners over a grid line) do not make prisms thinner than a double.
inline constexpr int kTilts = 3;
inline constexpr std::array<std::array<int, 2>, kTilts> kTiltEighths{{{1, -2}, {-2, 1}, {3, 2}}};

struct ProjectionOptions {
  // The projection axis; auto (none given) takes the one with the fewest WALL triangles.
  bool auto_axis = true;
  Axis axis = Axis::z;
  int tilt = 0;  // 0: along the axis; 1 to kTilts: tilted (kTiltEighths, in eighths)
};

struct RationalPoint {
  mpq_class x, y, z;
};

struct ProjectionStats {
  Axis axis = Axis::z;
  int tilt = 0;
  Index triangles = 0, top = 0, bot = 0, wall = 0;
  Index plane_vertices = 0, plane_triangles = 0;  // the constrained triangulation
  Index prisms = 0, degenerate_prisms = 0;        // degenerate: two corners coincide
  Index tets = 0;
  Index boundary_steiner = 0, interior_steiner = 0;  // points beyond the input's
  mpq_class enclosed_volume;  // inside the outermost surfaces, from their triangles
  // Seconds by stage: classify, project, prisms, stitch, fill.
  std::vector<std::pair<std::string, double>> seconds;
};

struct ProjectionMesh {
  // The input points first (surface by surface, in their order), then the boundary Steiner
  // points, then one centre per prism.
  std::vector<RationalPoint> points;
  std::vector<std::array<Index, 4>> tets;  // positive orientation (element_mesh.hpp)
  std::vector<Index> tet_region;
  // The tets' faces on the surfaces, oriented out of the tet, with the surface they lie on.
  std::vector<std::array<Index, 3>> boundary_faces;
  std::vector<Index> boundary_surface;
  // The input triangle each boundary face lies in, by its corners (input points).
  std::vector<std::array<Index, 3>> boundary_carrier;
  ProjectionStats stats;
};

// Throws InputError naming the place when the surfaces turn out not to bound a volume
// (open, crossing, self-intersecting or inward), which the caller's checks should catch first.
ProjectionMesh tetrahedralize_by_projection(const std::vector<ProjectionSurface>& surfaces,
                                            const ProjectionOptions& options = {},
                                            const Progress& progress = {});

const char* axis_name(Axis axis);
// "z", or "z tilted by (1/8, -1/4)".
std::string direction_name(Axis axis, int tilt);

}  // namespace volmesh::tet
