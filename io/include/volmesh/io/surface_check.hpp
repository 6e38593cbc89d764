#pragma once
// Validation of a triangulated surface as the boundary of a solid.
#include <filesystem>
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

// Pairs of triangles (i < j, sorted) that intersect in more than a shared vertex or edge,
// using CGAL's exact predicates; any triangle soup is accepted, degenerate triangles are
// skipped. At most max_pairs are returned; *truncated tells whether more exist.
std::vector<std::pair<Index, Index>> find_self_intersections(const TriSurface& surface,
                                                             std::size_t max_pairs,
                                                             bool* truncated = nullptr);

}  // namespace volmesh
