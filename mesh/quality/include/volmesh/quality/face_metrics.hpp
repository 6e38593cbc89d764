#pragma once
// Finite-volume metrics of the faces of any PolyMesh, as OpenFOAM's checkMesh computes them
// (primitiveMeshTools / polyMeshTools), from face and cell geometry computed once.
// Each function returns one value per face.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "volmesh/core/geometry.hpp"
#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// OpenFOAM checkMesh's thresholds: it flags faces more skewed than kCheckMeshSkewness (its
// skewThreshold) and fails internal faces non-orthogonal by kCheckMeshNonOrthogonality
// degrees or more.
inline constexpr double kCheckMeshSkewness = 4.0;
inline constexpr double kCheckMeshNonOrthogonality = 90.0;

// Non-orthogonality in degrees, in [0, 180]: the angle between the face area vector and
//   internal faces: the owner → neighbour cell centre vector (checkMesh's definition);
//   boundary faces: the owner centre → face centre vector.
// checkMesh itself reports 0 for (non-coupled) boundary faces and takes its maximum,
// average and > 70° count over internal faces only; the quality report does the same and
// keeps the boundary values apart.
std::vector<double> face_non_orthogonality(const PolyMesh& mesh, const MeshGeometry& geometry);

// Per face, how many of the cell centres on its sides lie behind it (0-2): the pyramid on the
// face with its apex at that centre has a negative volume (below -1e-15 as
// primitiveMesh::checkFacePyramids tests it; checkMesh's count of "incorrectly oriented"
// faces is the sum over the faces). The
// centres are checkMesh's (checkmesh_cell_geometry), not the exact centroids: a centre
// that lies on a face's plane to within the difference decides the verdict.
std::vector<std::uint8_t> face_inverted_pyramids(const PolyMesh& mesh, const CellFaces& cell_faces,
                                                 const MeshGeometry& geometry);

// Skewness exactly as primitiveMeshTools::faceSkewness (internal faces) and
// boundaryFaceSkewness (boundary faces, mirrored owner centre) define it: the distance
// between the face centre and the point where the centre-to-centre line crosses the face
// plane, divided by max(kInternalSkewnessFactor·|d|, the face's extent from its centre along
// that offset); on boundary faces d is the owner's normal distance to the face and the
// factor kBoundarySkewnessFactor. checkMesh flags faces above kCheckMeshSkewness.
std::vector<double> face_skewness(const PolyMesh& mesh, const MeshGeometry& geometry);

// OpenFOAM's ROOTVSMALL, kept in the formulas so that values match checkMesh's, including
// its answers for zero-area faces and coincident centres.
inline constexpr double kRootVSmall = 1e-150;

// The least extent of a face in the skewness, as a fraction of the centre distance |d|:
// OpenFOAM's 0.2 for internal faces, and 0.4 for boundary faces, whose d is half that to the
// mirror cell.
inline constexpr double kInternalSkewnessFactor = 0.2;
inline constexpr double kBoundarySkewnessFactor = 0.4;

// One face at a time, for meshers that weigh alternatives before the mesh exists: the face's
// centre and area vector, its vertices points[loop[k]], the cells' centres (no neighbour: a
// boundary face).

// primitiveMeshTools::faceSkewness with d the owner → neighbour centre vector, or
// boundaryFaceSkewness with d the owner's normal distance to the face.
// skewness_offset is its first part: the face centre's offset from where d crosses the
// face's plane, and the least extent the offset's length is divided by (factor * |d|).
struct SkewnessOffset {
  Vec3 offset;
  double min_extent;
};
inline SkewnessOffset skewness_offset(const FaceGeometry& face, const Vec3& owner, const Vec3* neighbour) {
  const Vec3 cpf = face.centre - owner;
  const Vec3& s = face.area_vector;
  Vec3 d;
  double factor;
  if (neighbour) {
    d = *neighbour - owner;
    factor = kInternalSkewnessFactor;
  } else {
    const Vec3 normal = s / (s.norm() + kRootVSmall);
    d = normal * normal.dot(cpf);
    factor = kBoundarySkewnessFactor;
  }
  return {cpf - (s.dot(cpf) / (s.dot(d) + kRootVSmall)) * d, factor * d.norm() + kRootVSmall};
}
template <class Points, class Loop>
double face_skewness(const FaceGeometry& face, const Points& points, const Loop& loop,
                     const Vec3& owner, const Vec3* neighbour) {
  const SkewnessOffset o = skewness_offset(face, owner, neighbour);
  const Vec3 sv_hat = o.offset / (o.offset.norm() + kRootVSmall);
  double extent = o.min_extent;
  for (const auto v : loop) extent = std::max(extent, std::abs(sv_hat.dot(points[v] - face.centre)));
  return o.offset.norm() / extent;
}

// Degrees between d and the area vector s. checkMesh takes acos of the normalised dot
// product; atan2 gives the same angle without losing half the digits near 0°. A zero vector
// gives 90°, as checkMesh's ROOTVSMALL guard makes it.
double non_orthogonality_deg(const Vec3& d, const Vec3& s);

// The limits a mesher holds its faces to, so that checkMesh accepts what the mesher accepts.
// Each lies a margin inside checkMesh's threshold: a mesher judges a face by its own estimate
// of the geometry before the mesh is final (the cell split from its pieces' exact
// centroids, not checkMesh's cell centres), and checkMesh measures a warped polygon (a face
// joined from several) about 1.5% more skewed than volmesh does.
struct CheckMeshLimits {
  double skewness = 3.9;
  double non_orthogonality = 88.0;  // degrees
};

// How far one face is from the limits: max(skewness / limits.skewness,
// non-orthogonality / limits.non_orthogonality), above 1 where the face is rejected; when a
// cell centre lies behind the face (checkMesh's incorrectly oriented face pyramid)
// kInvertedFace and more the farther behind, so that a change that moves it only part of
// the way back counts as progress.
inline constexpr double kInvertedFace = 1e3;
template <class Points, class Loop>
double checkmesh_badness(const FaceGeometry& face, const Points& points, const Loop& loop,
                         const Vec3& owner, const Vec3* neighbour, const CheckMeshLimits& limits) {
  const Vec3& s = face.area_vector;
  const Vec3 cpf = face.centre - owner;
  double behind = s.dot(cpf) / (s.norm() * cpf.norm() + kRootVSmall);
  if (neighbour) {
    const Vec3 cnf = *neighbour - face.centre;
    behind = std::min(behind, s.dot(cnf) / (s.norm() * cnf.norm() + kRootVSmall));
  }
  if (behind <= 0.0) return kInvertedFace * (1.0 - behind);
  const double angle = neighbour ? non_orthogonality_deg(*neighbour - owner, s) / limits.non_orthogonality : 0.0;
  return std::max(angle, face_skewness(face, points, loop, owner, neighbour) / limits.skewness);
}

// What surely_within_checkmesh_limits takes as surely within the limits: each centre in
// front of the face by more than kSureFront of the two vectors' lengths (a centre on the
// face's plane to rounding is left to checkmesh_badness); a non-orthogonality below
// kSureNonOrthogonalityDeg, tested without an arctangent as sine <= kSureTangent · cosine
// (tan 80° = 5.671: the test errs to the safe side), which settles only limits above that
// angle; a skewness below kSureSkewnessFraction of its limit even over the least extent (the
// face's own extent can only be larger), the last 1% a margin for rounding.
inline constexpr double kSureFront = 1e-12;
inline constexpr double kSureNonOrthogonalityDeg = 80.0;
inline constexpr double kSureTangent = 5.67;
inline constexpr double kSureSkewnessFraction = 0.99;

// Whether checkmesh_badness is surely at most 1, without the face's vertices or an
// arctangent (the constants above). Most faces of a mesh pass; false leaves the verdict to
// checkmesh_badness.
inline bool surely_within_checkmesh_limits(const FaceGeometry& face, const Vec3& owner, const Vec3* neighbour,
                                           const CheckMeshLimits& limits) {
  const Vec3& s = face.area_vector;
  const Vec3 cpf = face.centre - owner;
  const double size = s.norm();
  if (!(s.dot(cpf) > kSureFront * size * cpf.norm())) return false;
  if (neighbour) {
    const Vec3 cnf = *neighbour - face.centre;
    if (!(s.dot(cnf) > kSureFront * size * cnf.norm())) return false;
    const Vec3 d = *neighbour - owner;
    const double cosine = d.dot(s);
    if (!(limits.non_orthogonality > kSureNonOrthogonalityDeg && cosine > 0.0 &&
          d.cross(s).norm() <= kSureTangent * cosine))
      return false;
  }
  const SkewnessOffset o = skewness_offset(face, owner, neighbour);
  return o.offset.norm() <= kSureSkewnessFraction * limits.skewness * o.min_extent;
}

// Larger / smaller |volume| of the two cells across each internal face (>= 1; +inf when a
// cell has zero volume); NaN on boundary faces.
std::vector<double> face_volume_ratio(const PolyMesh& mesh, const MeshGeometry& geometry);

}  // namespace volmesh
