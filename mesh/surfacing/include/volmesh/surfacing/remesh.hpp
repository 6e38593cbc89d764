#pragma once
// A closed triangulated surface remeshed to a target edge (tet-front --remesh-surface), with
// how far it moved from the input.
//
// CGAL's Polygon_mesh_processing: the edges whose dihedral angle departs from flat by more
// than kSharpAngleDegrees are detected (detect_sharp_edges) and split to at most 4/3 h, then
// kept as constraints — neither split, collapsed nor flipped — while isotropic_remeshing
// splits, collapses, flips and smooths the rest toward edge h, projecting onto the input.
// The Hausdorff distance is measured both ways, to within kHausdorffErrorPerEdge·h
// (bounded_error_Hausdorff_distance). Deterministic.
#include "volmesh/core/tri_surface.hpp"

namespace volmesh::surfacing {

inline constexpr double kSharpAngleDegrees = 60.0;
inline constexpr int kRemeshIterations = 5;
inline constexpr double kHausdorffErrorPerEdge = 1e-3;

struct Remeshed {
  TriSurface surface;
  long long sharp_edges = 0;  // input edges kept as constraints
  // max over the remeshed surface of the distance to the input, and the other way.
  double hausdorff_to_input = 0.0, hausdorff_from_input = 0.0;
};

// `input`: closed, manifold, consistently oriented (check_surface); the result is oriented
// as the input. Throws InputError if h is not positive and finite.
Remeshed remesh_isotropic(const TriSurface& input, double h);

}  // namespace volmesh::surfacing
