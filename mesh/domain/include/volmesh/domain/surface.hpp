#pragma once
// Domains bounded by closed triangulated surfaces (docs/methods.md, "Domains"): one surface
// makes one solid; surfaces nested in each other make nested regions.
//
//  - region(p): the label of the innermost surface containing p, 0 outside all. Surfaces
//    must not cross each other; their nesting is found once, from one vertex of each. A point
//    on a surface is inside it (so on an inner surface it gets the inner label, as the
//    Domain contract gives interface points the higher-priority region).
//    Containment is the exact winding number: CGAL's exact orientation predicates count the
//    signed crossings of a ray, which is shot again in another direction when it meets an
//    edge or a vertex. Exact for any point, on or 1e-300 off the surface; a point where a
//    self-intersecting scan overlaps itself (winding number 2) is inside.
//  - crossings(a, b): every triangle the segment meets, found through a CGAL AABB tree with
//    exact predicates. A crossing through a shared edge or vertex counts once. t is computed
//    in double from the signed volumes (relative error ~1e-16 for crossings at a fair angle).
//    Regions between crossings follow from the winding numbers; after a crossing through an
//    edge or a vertex, or along a segment running in a face, they are found again, exactly,
//    at the middle of the next piece. As for AnalyticDomain: crossings at t = 0 or 1 appear
//    when an end point lies on a surface; a segment touching a surface from outside at an
//    edge or a vertex gives a crossing with before == after, its normal pointing out of the
//    touched surface. Normals: the face normal, or the angle-weighted pseudo-normal of the
//    edge or vertex crossed, oriented from `before` into `after`.
//  - normal(p): the pseudo-normal (Bærentzen & Aanæs) of the surface feature closest to p —
//    face, edge or vertex — pointing out of the surface it belongs to.
#include <memory>
#include <string>
#include <vector>

#include "volmesh/core/tri_surface.hpp"
#include "volmesh/domain/domain.hpp"

namespace volmesh {

namespace surface {
struct DomainData;  // surface_domain_data.hpp
}

struct LabelledSurface {
  TriSurface surface;  // closed, manifold, consistently oriented (check_surface)
  // The region inside it and outside the surfaces nested in it; 0 gives 1 + the number of
  // surfaces around it (1 for the outermost).
  Index label = 0;
  std::string name = "surface";  // names it in error messages (e.g. its file)
};

class SurfaceDomain final : public Domain {
 public:
  // Throws InputError naming the surface and the triangle, edge or vertex if a surface is
  // not closed and manifold, is inconsistently oriented, has a degenerate triangle, or if a
  // label is negative. An inward surface is flipped.
  explicit SurfaceDomain(std::vector<LabelledSurface> surfaces);
  ~SurfaceDomain() override;
  SurfaceDomain(SurfaceDomain&&) noexcept;
  SurfaceDomain& operator=(SurfaceDomain&&) noexcept;

  using Domain::crossings;
  using Domain::region;
  Index region(const Vec3& p) const override;
  std::vector<Crossing> crossings(const Vec3& a, const Vec3& b) const override;
  Vec3 normal(const Vec3& p) const override;
  Box3 bounds() const override;  // the box of the outermost surfaces
  std::vector<Index> regions() const override;

  // Per surface, in the order given: its label and the number of surfaces around it.
  const std::vector<Index>& labels() const;
  const std::vector<Index>& depths() const;
  // Surface s as checked: oriented outward, only the points its triangles use.
  TriSurface surface(Index s) const;

 private:
  std::unique_ptr<const surface::DomainData> data_;
};

}  // namespace volmesh
