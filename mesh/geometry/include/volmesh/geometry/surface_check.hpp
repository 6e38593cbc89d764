#pragma once
// Validation of a triangulated surface as the boundary of a solid: topology (closed,
// manifold, consistently oriented) and exact geometry (no collinear corners; intersecting
// triangles reported). It reads no file: the surface readers check syntax and indices only,
// and any TriSurface, read or built, is checked here before it bounds a solid.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "volmesh/core/tri_surface.hpp"

namespace volmesh {

struct SurfaceReport {
  Index points = 0, triangles = 0, components = 0;
  Index unused_points = 0;
  bool flipped = false;             // the surface was oriented inward and has been flipped
  double area = 0.0, volume = 0.0;  // enclosed volume after orientation fix
  Vec3 bbox_min = Vec3::Zero(), bbox_max = Vec3::Zero();
  // Pairs of triangles that intersect other than at shared vertices/edges (first few).
  std::vector<std::pair<Index, Index>> self_intersections;
  bool self_intersections_truncated = false;
  std::vector<std::string> warnings;
};

struct SurfaceCheckOptions {
  bool find_self_intersections = true;
  std::size_t max_self_intersections = 10;
};

// Checks a surface meant to bound a solid and fixes its global orientation (outward).
// Throws InputError, naming `source` and the offending triangle/edge/vertex index, for:
// no triangles, NaN/Inf coordinates, indices out of range, degenerate triangles (a repeated
// vertex, or exactly collinear corners), non-manifold edges, boundary edges (holes),
// inconsistent orientation across an edge. If the enclosed volume is negative, every triangle
// is flipped (report.flipped, a warning). Self-intersections are reported, not thrown: the
// caller decides whether they are fatal.
SurfaceReport check_surface(TriSurface& surface, const std::string& source,
                            const SurfaceCheckOptions& options = {});

}  // namespace volmesh
