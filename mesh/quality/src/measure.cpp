#include "volmesh/quality/measurements.hpp"

#include <limits>

#include "volmesh/quality/face_metrics.hpp"
#include "volmesh/quality/hex_metrics.hpp"
#include "volmesh/quality/tet_metrics.hpp"

namespace volmesh {

namespace {

// Keeps the worst (largest) value; a NaN slot means "nothing yet".
void raise(double& slot, double value) {
  if (!(slot >= value)) slot = value;
}

void measure_shapes(const PolyMesh& mesh, const CellFaces& cell_faces, CellQuality& q) {
  const auto& p = mesh.points;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const CellCorners cc = classify_cell(mesh, cell_faces, c);
    q.shape[c] = cc.shape;
    const auto& k = cc.corners;
    if (cc.shape == CellShape::Tetrahedron) {
      const TetMetrics t = tet_metrics(p[k[0]], p[k[1]], p[k[2]], p[k[3]]);
      q.min_dihedral[c] = t.min_dihedral_deg;
      q.max_dihedral[c] = t.max_dihedral_deg;
      q.radius_edge_ratio[c] = t.radius_edge_ratio;
      q.aspect_ratio[c] = t.aspect_ratio;
    } else if (cc.shape == CellShape::Hexahedron) {
      q.scaled_jacobian[c] = hex_scaled_jacobian(
          {p[k[0]], p[k[1]], p[k[2]], p[k[3]], p[k[4]], p[k[5]], p[k[6]], p[k[7]]});
    }
  }
}

void gather_face_values(const PolyMesh& mesh, const FaceQuality& faces, CellQuality& q) {
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Index owner = mesh.owner[f];
    raise(q.skewness[owner], faces.skewness[f]);
    if (mesh.is_boundary(f)) {
      raise(q.boundary_non_orthogonality[owner], faces.non_orthogonality[f]);
      continue;
    }
    const Index neighbour = mesh.neighbour[f];
    raise(q.skewness[neighbour], faces.skewness[f]);
    for (Index c : {owner, neighbour}) {
      raise(q.non_orthogonality[c], faces.non_orthogonality[f]);
      raise(q.volume_ratio[c], faces.volume_ratio[f]);
    }
  }
}

}  // namespace

QualityMeasurements measure_quality(const PolyMesh& mesh, const CellFaces& cell_faces,
                                    const MeshGeometry& geometry) {
  const auto n = static_cast<std::size_t>(mesh.num_cells());
  QualityMeasurements m;
  CellQuality& q = m.cells;
  q.shape.resize(n);
  q.volume.resize(n);
  for (std::size_t c = 0; c < n; ++c) q.volume[c] = geometry.cells[c].volume;
  for (auto* a :
       {&q.scaled_jacobian, &q.min_dihedral, &q.max_dihedral, &q.radius_edge_ratio, &q.aspect_ratio,
        &q.non_orthogonality, &q.boundary_non_orthogonality, &q.skewness, &q.volume_ratio})
    a->assign(n, std::numeric_limits<double>::quiet_NaN());

  measure_shapes(mesh, cell_faces, q);
  m.faces = {face_non_orthogonality(mesh, geometry), face_skewness(mesh, geometry),
             face_volume_ratio(mesh, geometry), face_inverted_pyramids(mesh, cell_faces, geometry)};
  gather_face_values(mesh, m.faces, q);
  return m;
}

QualityMeasurements measure_quality(const PolyMesh& mesh) {
  const CellFaces cell_faces = build_cell_faces(mesh);
  return measure_quality(mesh, cell_faces, mesh_geometry(mesh, cell_faces));
}

}  // namespace volmesh
