#pragma once
// Closed triangulated surfaces prepared for distance and inside queries: checked for what
// those queries rely on, oriented outward, with the angle-weighted pseudo-normals of
// Bærentzen & Aanæs (2005), whose sign test is exact for the closest feature of a closed,
// manifold surface. Several surfaces are stored one after another.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "volmesh/core/tri_surface.hpp"
#include "volmesh/domain/domain.hpp"

namespace volmesh::surface {

// Where on a triangle (a, b, c) a point lies: its interior, side k (corner k to corner
// k + 1: ab, bc, ca) or corner k.
enum class Feature : std::uint8_t { face, edge0, edge1, edge2, vertex0, vertex1, vertex2 };

inline Feature edge_feature(int k) { return static_cast<Feature>(1 + k); }
inline Feature vertex_feature(int k) { return static_cast<Feature>(4 + k); }

struct SurfaceGeometry {
  std::vector<Vec3> points;                       // every surface's points, concatenated
  std::vector<std::array<Index, 3>> triangles;    // into points; outward (counter-clockwise)
  std::vector<Index> first_triangle{0};           // surface s: [first_triangle[s], [s + 1])
  std::vector<Index> triangle_surface;            // the surface of each triangle
  std::vector<Vec3> face_normals;                 // unit
  std::vector<std::array<Vec3, 3>> edge_normals;  // per side: the two faces' normals' sum, unit
  std::vector<Vec3> vertex_normals;               // faces' normals by their angle there, unit

  Index num_surfaces() const { return static_cast<Index>(first_triangle.size()) - 1; }
  Index num_triangles() const { return static_cast<Index>(triangles.size()); }
  const Vec3& corner(Index t, int k) const { return points[triangles[t][k]]; }
  // Unit outward pseudo-normal of a feature of triangle t.
  const Vec3& normal(Index t, Feature f) const;
};

// Appends a surface. Throws InputError "NAME: ..." naming the triangle, edge or vertex for
// what the queries cannot work with: no triangles, non-finite coordinates, indices out of
// range, degenerate triangles (collinear corners, to rounding), an edge not shared by
// exactly two triangles (a hole or a non-manifold edge), or two triangles running along an
// edge in the same direction. A surface enclosing a negative volume is flipped, as
// check_surface does.
void add_surface(SurfaceGeometry& geometry, TriSurface surface, const std::string& name);

// The box of the triangles (unused points left out); the geometry must not be empty.
Box3 bounding_box(const SurfaceGeometry& geometry);

}  // namespace volmesh::surface
