#include "volmesh/quality/face_metrics.hpp"

#include <oneapi/tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace volmesh {

double non_orthogonality_deg(const Vec3& d, const Vec3& s) {
  const double sine = d.cross(s).norm(), cosine = d.dot(s);
  if (sine == 0.0 && cosine == 0.0) return 90.0;
  return std::atan2(sine, cosine) * (180.0 / std::numbers::pi);
}

std::vector<double> face_non_orthogonality(const PolyMesh& mesh, const MeshGeometry& geometry) {
  std::vector<double> out(mesh.num_faces());
  tbb::parallel_for(Index{0}, mesh.num_faces(), [&](Index f) {
    const FaceGeometry& face = geometry.faces[f];
    const Vec3& owner = geometry.cells[mesh.owner[f]].centre;
    const Vec3& other =
        mesh.is_boundary(f) ? face.centre : geometry.cells[mesh.neighbour[f]].centre;
    out[f] = non_orthogonality_deg(other - owner, face.area_vector);
  });
  return out;
}

std::vector<std::uint8_t> face_inverted_pyramids(const PolyMesh& mesh, const CellFaces& cell_faces,
                                                 const MeshGeometry& geometry) {
  constexpr double kMinPyramidVolume = -1e-15;  // OpenFOAM's -SMALL
  std::vector<Vec3> centre(mesh.num_cells());
  tbb::parallel_for(Index{0}, mesh.num_cells(), [&](Index c) {
    centre[c] = checkmesh_cell_geometry([&](const auto& visit) {
                  for (const Index f : cell_faces.of(c)) {
                    const FaceGeometry& face = geometry.faces[f];
                    visit(mesh.owner[f] == c ? face.area_vector : Vec3(-face.area_vector), face.centre);
                  }
                }).centre;
  });
  std::vector<std::uint8_t> out(mesh.num_faces());
  tbb::parallel_for(Index{0}, mesh.num_faces(), [&](Index f) {
    const FaceGeometry& face = geometry.faces[f];
    const double owner = face.area_vector.dot(face.centre - centre[mesh.owner[f]]) / 3.0;
    const double neighbour =
        mesh.is_boundary(f) ? 0.0 : face.area_vector.dot(centre[mesh.neighbour[f]] - face.centre) / 3.0;
    out[f] = (owner < kMinPyramidVolume ? 1 : 0) + (neighbour < kMinPyramidVolume ? 1 : 0);
  });
  return out;
}

std::vector<double> face_skewness(const PolyMesh& mesh, const MeshGeometry& geometry) {
  std::vector<double> out(mesh.num_faces());
  tbb::parallel_for(Index{0}, mesh.num_faces(), [&](Index f) {
    const Vec3* neighbour = mesh.is_boundary(f) ? nullptr : &geometry.cells[mesh.neighbour[f]].centre;
    out[f] = face_skewness(geometry.faces[f], mesh.points, mesh.face(f),
                           geometry.cells[mesh.owner[f]].centre, neighbour);
  });
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
