#pragma once
// Finite-volume metrics of the faces of any PolyMesh, as OpenFOAM's checkMesh computes them
// (primitiveMeshTools / polyMeshTools), from face and cell geometry computed once.
// Each function returns one value per face.
#include <vector>

#include "volmesh/core/geometry.hpp"
#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// Non-orthogonality in degrees, in [0, 180]: the angle between the face area vector and
//   internal faces: the owner → neighbour cell centre vector (checkMesh's definition);
//   boundary faces: the owner centre → face centre vector.
// checkMesh itself reports 0 for (non-coupled) boundary faces and takes its maximum,
// average and > 70° count over internal faces only; the quality report does the same and
// keeps the boundary values apart.
std::vector<double> face_non_orthogonality(const PolyMesh& mesh, const MeshGeometry& geometry);

// Skewness exactly as primitiveMeshTools::faceSkewness (internal faces) and
// boundaryFaceSkewness (boundary faces, mirrored owner centre) define it: the distance
// between the face centre and the point where the centre-to-centre line crosses the face
// plane, divided by max(0.2·|d|, the face's extent from its centre along that offset);
// on boundary faces d is the owner's normal distance to the face and the factor 0.4.
// checkMesh flags faces above 4.
std::vector<double> face_skewness(const PolyMesh& mesh, const MeshGeometry& geometry);

// Larger / smaller |volume| of the two cells across each internal face (>= 1; +inf when a
// cell has zero volume); NaN on boundary faces.
std::vector<double> face_volume_ratio(const PolyMesh& mesh, const MeshGeometry& geometry);

}  // namespace volmesh
