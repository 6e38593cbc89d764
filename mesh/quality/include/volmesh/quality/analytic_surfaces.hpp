#pragma once
// The TRUE surfaces of an analytic domain as a reference for surface_distance: exact
// distances through the primitives' closest points (volmesh/domain/analytic_closest.hpp),
// samples on every primitive's surface, sharp edges by primitive; and the exact volumes the
// mesh's regions are compared with.
#include <map>
#include <string>
#include <vector>

#include "volmesh/domain/analytic.hpp"
#include "volmesh/domain/analytic_closest.hpp"
#include "volmesh/quality/surface_distance.hpp"

namespace volmesh {

// The union of the domain's primitive surfaces. That union is the true interface set when
// every primitive's whole surface separates two regions: a single solid, nested solids
// (builtin:thick-sphere, builtin:cube-inclusion) or multi_material_domain; not general CSG,
// where parts of a surface lie inside a region. One part per primitive; one feature group per
// primitive with sharp edges (boxes, cylinders), named as the primitive.
class AnalyticSurfaces final : public ReferenceSurface {
 public:
  explicit AnalyticSurfaces(const AnalyticDomain& domain);

  double distance(const Vec3& p) const override;
  std::size_t num_parts() const override { return primitives_.size(); }
  void sample(std::size_t part, double spacing, std::vector<Vec3>& out) const override;
  std::vector<std::string> feature_groups() const override;
  double feature_distance(std::size_t group, const Vec3& p) const override;

 private:
  std::vector<Primitive> primitives_;
  std::vector<std::size_t> sharp_;  // the primitive of each feature group
};

// Distance from p (world coordinates) to the primitive's sharp edges (the 12 edges of a box,
// the 2 rims of a cylinder); +infinity for smooth primitives.
double sharp_edge_distance(const Primitive& primitive, const Vec3& p);

// Points on the primitive's surface with their outward unit normals, every point of the
// surface within `spacing` of one, sharp edges included: Fibonacci points on spheres and
// ellipsoids, parameter grids on tori, boxes and cylinders. Half-spaces are unbounded: none.
std::vector<SurfacePoint> sample_surface(const Primitive& primitive, double spacing);

// Volume enclosed by the primitive (+infinity for a half-space).
double solid_volume(const Primitive& primitive);

// The exact volume of each region of the domain named `spec` (as on the command line) where a
// closed form is known: a built-in domain's (builtin_region_volumes), or the solid's own for
// an analytic domain of one primitive and one region. Empty otherwise.
std::map<Index, double> exact_region_volumes(const std::string& spec, const Domain& domain);

}  // namespace volmesh
