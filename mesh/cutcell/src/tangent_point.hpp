#pragma once
// Points from interface points s_i and their unit normals n_i: the least-squares intersection
// of the tangent planes, system (2) of the octree paper,
//   [..., n_i, ...]^T p = [..., n_i . s_i, ...],
// solved through the SVD pseudo-inverse relative to the mass point of the s_i, so that a
// direction the normals do not constrain leaves p at the mass point (EMC, Kobbelt et al.).
// In a face, the normals projected on the face plane give the intersection of the tangent
// lines; it stays in the plane of the s_i.
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "volmesh/core/types.hpp"

namespace volmesh::cutcell {

// Singular values below `relative_cutoff` times the largest are dropped, and at most
// `max_rank` are kept (EMC truncates to rank 2 along a sharp edge). The default drops a
// direction the normals fix less than a tenth as firmly as the firmest one: two normals less
// than about 11 degrees apart fix one direction, not two.
inline constexpr double kRelativeCutoff = 0.1;
Vec3 tangent_intersection(std::span<const Vec3> points, std::span<const Vec3> normals,
                          int max_rank = 3, double relative_cutoff = kRelativeCutoff);
// The same relative to `origin` instead of the mass point: unconstrained directions keep
// origin's coordinates.
Vec3 tangent_intersection(std::span<const Vec3> points, std::span<const Vec3> normals,
                          const Vec3& origin, int max_rank = 3,
                          double relative_cutoff = kRelativeCutoff);

// The same with the points in priority levels, 0 first: each level fits only the directions
// the earlier levels leave free. A junction with the domain's boundary (level 0) stays on the
// boundary's tangent planes (exactly on a planar face or edge) whatever the interior
// interfaces meeting it do.
Vec3 tangent_intersection_ranked(std::span<const Vec3> points, std::span<const Vec3> normals,
                                 std::span<const std::uint8_t> level, int max_rank = 3,
                                 double relative_cutoff = kRelativeCutoff);

// The direction the normals leave free, when the least-squares fit drops it (its squared
// singular value at most relative_cutoff^2 of the largest): along a junction line, where the
// tangent planes of two or more surfaces meet.
std::optional<Vec3> free_direction(std::span<const Vec3> normals,
                                   double relative_cutoff = kRelativeCutoff);

// Unit normals whose cosine exceeds 1 - kSameDirection have one direction: the normals of one
// plane agree to rounding.
inline constexpr double kSameDirection = 1e-12;

// Normals within about 26 degrees of each other (cosine above this) belong to one surface.
inline constexpr double kSameSurfaceCosine = 0.9;

// The interface found again near x: the crossing nearest x of the segment x -+ d whose
// normal lies within about 26 degrees of d, with that normal; nullopt if none.
using SurfaceNear = std::function<std::optional<std::pair<Vec3, Vec3>>(const Vec3& x, const Vec3& d)>;

struct TangentPlanes {
  std::vector<Vec3> points, normals;
};
// The tangent planes of the surfaces meeting at a feature point x, found again beside it:
// the normals n (at points s) grouped into surfaces (kSameSurfaceCosine), each surface found
// on the segment x -+ reach * m, m the normal of its point nearest x, moved `shift` along the
// surface toward its points (a surface ending at the feature lies on that side). Where the
// new planes meet is one Newton step from x: off the surfaces by the square of x's distance,
// where the planes of points a cell away meet off a curved surface by d^2 / 2r. nullopt for
// fewer than two surfaces, or one not found again.
std::optional<TangentPlanes> planes_near_feature(std::span<const Vec3> s, std::span<const Vec3> n,
                                                 const Vec3& x, double reach, double shift,
                                                 const SurfaceNear& near);

// Whether a unit normal is exactly an axis: the plane is parallel to the octree's faces (a
// box's face), the only boundary planes points are moved back onto.
inline bool parallel_to_octree_faces(const Vec3& normal) {
  return (normal.cwiseAbs().array() == 1.0).any();
}

// Whether the normals take at most max_planes directions (to rounding), each at min_points
// points or more unless it is an axis: the points lie on that many planes, as on a box's
// faces, rather than on a curved surface (a direction seen once may be one normal of a curved
// surface; an axis seen once is a box's face that only grazes the cell).
bool few_directions(std::span<const Vec3> normals, int max_planes, int min_points = 1);

// The Kobbelt/EMC feature test on one contour component: theta = min n_i . n_j; a sharp
// feature when theta < theta_s. With n* = n0 x n1 for the pair of least dot product,
// phi = max |n_i . n*| > phi_s makes it a corner (rank 3), otherwise an edge (rank 2).
struct FeatureThresholds {
  double theta = 0.9;
  double phi = 0.7;
};
struct Feature {
  Vec3 point;
  bool corner;
};
// `level` as in tangent_intersection_ranked (empty: one level).
std::optional<Feature> sharp_feature(std::span<const Vec3> points, std::span<const Vec3> normals,
                                     const FeatureThresholds& thresholds = {},
                                     std::span<const std::uint8_t> level = {});

}  // namespace volmesh::cutcell
