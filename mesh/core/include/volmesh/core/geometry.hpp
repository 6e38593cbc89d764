#pragma once
// Face and cell geometry of polygonal faces and polyhedral cells, computed as OpenFOAM does:
// a face is decomposed into triangles around its vertex average, a cell into pyramids on
// those triangles around an estimated centre. Both neighbours of a face use the same
// decomposition, so cell volumes add up exactly to the domain volume.
#include <algorithm>
#include <span>
#include <vector>

#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

struct FaceGeometry {
  Vec3 area_vector;  // right-hand normal times area
  Vec3 centre;
};
FaceGeometry face_geometry(const PolyMesh& mesh, Index f);
FaceGeometry polygon_geometry(const std::vector<Vec3>& points, std::span<const Index> loop);

// Whether every triangle of the fan around the loop's vertex average faces the way the whole
// polygon does (each by more than a rounding floor): the decomposition above then covers the
// polygon once.
bool fan_is_proper(const std::vector<Vec3>& points, std::span<const Index> loop);

struct CellGeometry {
  double volume;
  Vec3 centre;
};
// Signed volume and centroid of a cell from its faces (outward orientation assumed).
CellGeometry cell_geometry(const PolyMesh& mesh, std::span<const Index> faces, Index c,
                           const std::vector<FaceGeometry>& face_geom);

struct MeshGeometry {
  std::vector<FaceGeometry> faces;
  std::vector<CellGeometry> cells;
};
MeshGeometry mesh_geometry(const PolyMesh& mesh, const CellFaces& cell_faces);

// Signed volume of the tetrahedron (a, b, c, d): positive when det(b-a, c-a, d-a) > 0.
inline double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

// Distance from p to the segment a-b.
inline double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a, ap = p - a;
  const double t = std::clamp(ap.dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (ap - t * ab).norm();
}

}  // namespace volmesh
