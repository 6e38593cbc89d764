#pragma once
// Geometric error of a mesh against the analytic domain it was made from (DESIGN.md §5,
// issue 4): region volumes, and the two-sided Hausdorff distance between the mesh's
// boundaries and interfaces and the TRUE analytic surfaces — over the whole surface and near
// the sharp feature edges (box edges, cylinder rims). Used by tests/geometry and by the
// study in validation/geometry; it lives here because the test suite compiles this folder.
#include <algorithm>
#include <limits>
#include <map>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/domain/analytic.hpp"

namespace volmesh::geometry {

// ---- one analytic primitive (analytic_surface.cpp) ----

// Exact distance from p (world coordinates) to the primitive's surface, through
// closest_surface_point (volmesh/domain/analytic_closest.hpp).
double surface_distance(const Primitive& primitive, const Vec3& p);
// Distance from p to the primitive's sharp edges (the 12 edges of a box, the 2 rims of a
// cylinder); +infinity for smooth primitives.
double feature_distance(const Primitive& primitive, const Vec3& p);
// Points on the primitive's surface, no two neighbours farther apart than about `spacing`,
// sharp edges included, with the outward unit normal. Half-spaces are unbounded: none.
struct SurfacePoint {
  Vec3 point, normal;
};
std::vector<SurfacePoint> sample_surface(const Primitive& primitive, double spacing);
// Volume enclosed by the primitive (+infinity for a half-space).
double solid_volume(const Primitive& primitive);

// ---- a mesh against the domain (mesh_hausdorff.cpp) ----

struct OneSided {
  double mesh_to_surface = 0.0;  // max over mesh samples of the distance to the true surface
  double surface_to_mesh = 0.0;  // max over true-surface samples of the distance to the mesh
  Index mesh_samples = 0, surface_samples = 0;
  Vec3 mesh_worst = Vec3::Zero(), surface_worst = Vec3::Zero();  // where the maxima are
  double hausdorff() const { return std::max(mesh_to_surface, surface_to_mesh); }
};
struct HausdorffReport {
  OneSided all;
  // Per primitive (in the domain's order): the samples within the feature band of its sharp
  // edges (none for smooth primitives, or when the band is 0).
  std::vector<OneSided> features;
};

struct HausdorffOptions {
  double spacing = 0.01;      // of the samples on the true surface and inside mesh triangles
  double feature_band = 0.0;  // samples this close to a sharp edge count for `features`
};

// The mesh's boundary faces and its faces between two regions, against the union of the
// domain's primitive surfaces. That union is the true interface set when every primitive's
// whole surface separates two regions: a single solid, or multi_material_domain (not
// general CSG, where parts of a surface lie inside a region). Mesh faces are split into
// triangles around their vertex average; each triangle is sampled at its vertices, edge
// midpoints, centroid and a barycentric grid no coarser than `spacing`; the distance to the
// mesh is the distance to the nearest triangle (CGAL AABB tree). Both cores.
HausdorffReport hausdorff(const PolyMesh& mesh, const AnalyticDomain& domain,
                          const HausdorffOptions& options);

// Volume of each region of the mesh (cells summed as OpenFOAM computes them).
std::map<Index, double> region_volumes(const PolyMesh& mesh);

// Least-squares slope of log(error) against log(h): the observed order of convergence.
double convergence_slope(const std::vector<double>& h, const std::vector<double>& error);

}  // namespace volmesh::geometry
