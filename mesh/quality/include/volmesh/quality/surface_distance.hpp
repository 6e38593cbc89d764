#pragma once
// How far a mesh's boundary lies from the surface it approximates (docs/verification.md,
// "Geometric convergence"): the
// two-sided distance between the mesh's boundary faces (and interfaces) and a reference
// surface, each side a maximum found within a stated tolerance of the true one.
//
// One driver serves every reference through ReferenceSurface. A reference that is a
// triangulation is measured on both sides by bounded subdivision: exact point-triangle
// distances at the corners of pieces, pieces subdivided farthest first until no piece can
// hold a point farther than the maximum found plus the tolerance. Any other reference (an
// analytic domain's surfaces, analytic_surfaces.hpp) is measured by samples: points on each
// side no farther than the tolerance from every point of it, their exact distances to the
// other side. Either way each one-sided maximum is the distance of a point found on that
// side, so it is at most the true maximum and, the distance being 1-Lipschitz, at least the
// true maximum minus the tolerance.
#include <memory>
#include <string>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"
#include "volmesh/core/tri_surface.hpp"

namespace volmesh {

class TriangulatedSurface;

// One side: the largest distance found from a point of one surface to the other.
struct FarthestPoint {
  double distance = 0.0;
  Vec3 at = Vec3::Zero();  // the point it was found at (the first one, for ties)
  Index points = 0;        // points whose distance was evaluated
};

// The surface a mesh is measured against, as the driver sees it.
class ReferenceSurface {
 public:
  virtual ~ReferenceSurface() = default;

  // The exact distance from p to the surface. Called from several threads at once.
  virtual double distance(const Vec3& p) const = 0;

  // The surface in parts (triangles, primitives), and points on a part such that every point
  // of the part lies within `spacing` of one of them. Appends to `out`.
  virtual std::size_t num_parts() const = 0;
  virtual void sample(std::size_t part, double spacing, std::vector<Vec3>& out) const = 0;

  // Groups of sharp edges (where the surface has no tangent plane: a box's edges, a
  // cylinder's rims), by name, and the distance from p to a group's edges. None by default.
  virtual std::vector<std::string> feature_groups() const { return {}; }
  virtual double feature_distance(std::size_t group, const Vec3& p) const;

  // The surface itself when it is a triangulation: the driver then bounds instead of samples.
  virtual const TriangulatedSurface* triangulation() const { return nullptr; }
};

// A triangulated surface as a reference (a CGAL AABB tree answers the distance queries).
class TriangulatedSurface final : public ReferenceSurface {
 public:
  // Throws std::invalid_argument for a surface without triangles.
  explicit TriangulatedSurface(TriSurface surface);
  ~TriangulatedSurface() override;
  TriangulatedSurface(const TriangulatedSurface&) = delete;
  TriangulatedSurface& operator=(const TriangulatedSurface&) = delete;

  double distance(const Vec3& p) const override;
  // One part per triangle, sampled on a barycentric grid (its corners, edge midpoints and
  // centroid included).
  std::size_t num_parts() const override { return surface_.triangles.size(); }
  void sample(std::size_t part, double spacing, std::vector<Vec3>& out) const override;
  const TriangulatedSurface* triangulation() const override { return this; }

  const TriSurface& surface() const { return surface_; }
  // The largest distance from a point of `from` to this surface, within `error_bound` below
  // the true maximum, by bounded subdivision of from's triangles.
  FarthestPoint farthest_from(const TriSurface& from, double error_bound) const;

 private:
  struct Tree;  // the AABB tree, private to the .cpp that includes CGAL
  TriSurface surface_;
  std::unique_ptr<Tree> tree_;
};

struct TwoSidedDistance {
  FarthestPoint mesh_to_surface, surface_to_mesh;
  double hausdorff() const {
    return mesh_to_surface.distance > surface_to_mesh.distance ? mesh_to_surface.distance
                                                               : surface_to_mesh.distance;
  }
};

struct SurfaceDistanceOptions {
  // Each one-sided maximum is found within this of the true one (> 0): the error bound of
  // the subdivision for a triangulated reference, the samples' spacing for any other.
  double tolerance = 0.0;
  // Sampled references: the points within this of a feature group's edges count for it too
  // (0: no per-feature figures).
  double feature_band = 0.0;
  // Also measure the faces between two regions (the reference holds every region's
  // boundary); otherwise only the mesh's boundary faces.
  bool interfaces = true;
};

struct SurfaceDistance {
  TwoSidedDistance all;
  // Per feature group of the reference (with a feature band): the maxima over the points
  // within the band of the group's edges.
  std::vector<TwoSidedDistance> features;
};

// The mesh's faces are split into triangles as boundary_surface does (polygons around their
// vertex average). Throws std::invalid_argument for a tolerance <= 0 or a mesh without the
// faces to measure. Sampling runs in parallel, the subdivision on one thread; the result
// does not depend on the thread count.
SurfaceDistance surface_distance(const PolyMesh& mesh, const ReferenceSurface& reference,
                                 const SurfaceDistanceOptions& options);

// Two triangulated surfaces: each side within `error_bound` below the true maximum. Pieces
// over coplanar triangles that cover them are bounded at once, so that a surface lying on
// the other's planar faces is measured in a fraction of a second.
struct HausdorffDistance {
  double from_a = 0.0;  // max over points of a of the distance to b
  double from_b = 0.0;  // max over points of b of the distance to a
  double symmetric() const { return from_a > from_b ? from_a : from_b; }
};
HausdorffDistance hausdorff_distance(const TriSurface& a, const TriSurface& b, double error_bound);

}  // namespace volmesh
