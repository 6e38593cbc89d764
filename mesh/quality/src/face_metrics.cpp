#include "volmesh/quality/face_metrics.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace volmesh {

namespace {

// OpenFOAM's ROOTVSMALL, kept in the skewness formula so that values match checkMesh's,
// including its answers for zero-area faces and coincident centres.
constexpr double kRootVSmall = 1e-150;

// checkMesh takes acos of the normalised dot product; atan2 gives the same angle without
// losing half the digits near 0°. A zero vector gives 90°, as checkMesh's ROOTVSMALL guard
// makes it, so that a zero-area face is not reported as perfectly orthogonal.
double angle_deg(const Vec3& d, const Vec3& s) {
  const double sine = d.cross(s).norm(), cosine = d.dot(s);
  if (sine == 0.0 && cosine == 0.0) return 90.0;
  return std::atan2(sine, cosine) * (180.0 / std::numbers::pi);
}

// primitiveMeshTools::faceSkewness with d the owner → (possibly mirrored) neighbour centre
// vector and `factor` times |d| the least normalisation distance.
double skewness(const PolyMesh& mesh, Index f, const FaceGeometry& face, const Vec3& owner_centre,
                const Vec3& d, double factor) {
  const Vec3 cpf = face.centre - owner_centre;
  const Vec3& s = face.area_vector;
  const Vec3 sv = cpf - (s.dot(cpf) / (s.dot(d) + kRootVSmall)) * d;
  const Vec3 sv_hat = sv / (sv.norm() + kRootVSmall);
  double extent = factor * d.norm() + kRootVSmall;
  for (Index v : mesh.face(f))
    extent = std::max(extent, std::abs(sv_hat.dot(mesh.points[v] - face.centre)));
  return sv.norm() / extent;
}

}  // namespace

std::vector<double> face_non_orthogonality(const PolyMesh& mesh, const MeshGeometry& geometry) {
  std::vector<double> out(mesh.num_faces());
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const FaceGeometry& face = geometry.faces[f];
    const Vec3& owner = geometry.cells[mesh.owner[f]].centre;
    const Vec3& other =
        mesh.is_boundary(f) ? face.centre : geometry.cells[mesh.neighbour[f]].centre;
    out[f] = angle_deg(other - owner, face.area_vector);
  }
  return out;
}

std::vector<double> face_skewness(const PolyMesh& mesh, const MeshGeometry& geometry) {
  std::vector<double> out(mesh.num_faces());
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const FaceGeometry& face = geometry.faces[f];
    const Vec3& owner = geometry.cells[mesh.owner[f]].centre;
    if (!mesh.is_boundary(f)) {
      out[f] =
          skewness(mesh, f, face, owner, geometry.cells[mesh.neighbour[f]].centre - owner, 0.2);
    } else {
      // d is the owner's normal distance to the face, half that to a mirror cell: hence 0.4.
      const Vec3 normal = face.area_vector / (face.area_vector.norm() + kRootVSmall);
      const Vec3 d = normal * normal.dot(face.centre - owner);
      out[f] = skewness(mesh, f, face, owner, d, 0.4);
    }
  }
  return out;
}

std::vector<double> face_volume_ratio(const PolyMesh& mesh, const MeshGeometry& geometry) {
  std::vector<double> out(mesh.num_faces(), std::numeric_limits<double>::quiet_NaN());
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.is_boundary(f)) continue;
    const double a = std::abs(geometry.cells[mesh.owner[f]].volume);
    const double b = std::abs(geometry.cells[mesh.neighbour[f]].volume);
    const double lo = std::min(a, b), hi = std::max(a, b);
    out[f] = lo > 0.0 ? hi / lo : std::numeric_limits<double>::infinity();
  }
  return out;
}

}  // namespace volmesh
