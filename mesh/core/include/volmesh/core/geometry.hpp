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

// A polygon's area over its longest side squared (the area given): near 0 when its vertices
// lie in a line up to rounding, and exactly 0 when they all coincide.
double flatness(const std::vector<Vec3>& points, std::span<const Index> loop, double area);

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

// Volume and centre of a cell as OpenFOAM's checkMesh computes them
// (primitiveMeshCellCentresAndVols): pyramids from the mean of the face centres to each
// face, each with its centroid 3/4 of the way to the face centre. On a warped face this
// differs from cell_geometry's exact centroid, and checkMesh's verdicts follow this one.
// for_each_face(visit) calls visit(area_vector, centre) for each face, the area vector
// pointing out of the cell; it is called twice.
template <class ForEachFace>
CellGeometry checkmesh_cell_geometry(const ForEachFace& for_each_face) {
  Vec3 estimate = Vec3::Zero();
  int count = 0;
  for_each_face([&](const Vec3&, const Vec3& centre) {
    estimate += centre;
    ++count;
  });
  estimate /= static_cast<double>(std::max(count, 1));
  double volume = 0.0;
  Vec3 moment = Vec3::Zero();
  for_each_face([&](const Vec3& area, const Vec3& centre) {
    const double v = area.dot(centre - estimate) / 3.0;
    volume += v;
    moment += v * (0.75 * centre + 0.25 * estimate);
  });
  return {volume, volume != 0.0 ? Vec3(moment / volume) : estimate};
}

struct MeshGeometry {
  std::vector<FaceGeometry> faces;
  std::vector<CellGeometry> cells;
};
MeshGeometry mesh_geometry(const PolyMesh& mesh, const CellFaces& cell_faces);
// The same with the faces' geometry known (face_geometry of each face).
MeshGeometry mesh_geometry(const PolyMesh& mesh, const CellFaces& cell_faces, std::vector<FaceGeometry> faces);

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
