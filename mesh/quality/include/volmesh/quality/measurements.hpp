#pragma once
// Every quality metric of a PolyMesh, measured in one pass over cells and faces from
// geometry computed once: the data behind the quality report and the VTU cell arrays.
#include <cstdint>
#include <string>
#include <vector>

#include "volmesh/core/convert.hpp"
#include "volmesh/core/geometry.hpp"
#include "volmesh/core/poly_mesh.hpp"

namespace volmesh {

// One value per cell; NaN where a metric does not apply to the cell's shape.
struct CellQuality {
  std::vector<CellShape> shape;         // tets and hexes as classify_cell recognises them
  std::vector<double> volume;           // signed, from mesh_geometry
  std::vector<double> scaled_jacobian;  // hexes (hex_metrics.hpp)
  std::vector<double> min_dihedral, max_dihedral;       // tets, degrees (tet_metrics.hpp)
  std::vector<double> radius_edge_ratio, aspect_ratio;  // tets
  // Worst value over the cell's faces (face_metrics.hpp); NaN if the cell has none of them.
  std::vector<double> non_orthogonality;           // internal faces, as checkMesh's cell field
  std::vector<double> boundary_non_orthogonality;  // boundary faces
  std::vector<double> skewness;                    // all faces
  std::vector<double> volume_ratio;                // internal faces
};

// One value per face, as face_metrics.hpp defines them.
struct FaceQuality {
  std::vector<double> non_orthogonality, skewness, volume_ratio;
  std::vector<std::uint8_t> inverted_pyramids;
};

struct QualityMeasurements {
  CellQuality cells;
  FaceQuality faces;
};

QualityMeasurements measure_quality(const PolyMesh& mesh, const CellFaces& cell_faces,
                                    const MeshGeometry& geometry);
// Builds the cell faces and the geometry first.
QualityMeasurements measure_quality(const PolyMesh& mesh);

// The per-cell values under the names they carry as VTU cell data: "volume",
// "scaled_jacobian", "min_dihedral", "max_dihedral", "radius_edge_ratio", "aspect_ratio",
// "non_orthogonality", "boundary_non_orthogonality", "skewness", "volume_ratio".
struct NamedArray {
  std::string name;
  std::vector<double> values;
};
std::vector<NamedArray> cell_quality_arrays(CellQuality cells);
std::vector<NamedArray> cell_quality_arrays(const PolyMesh& mesh);

}  // namespace volmesh
